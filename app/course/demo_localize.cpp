#include "app/course/demo_localize.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "app/course/demo_localize_text.hpp"
#include "app/run/localization.hpp"
#include "app/run/option_values.hpp"
#include "app/run/shipped_worlds.hpp"
#include "common/error.hpp"
#include "common/random.hpp"
#include "maze/world/world.hpp"

namespace app::course {
namespace {

constexpr std::size_t kMaxCells = 400;
constexpr int kMaxParticles = 1000000;
constexpr std::uint64_t kParticleStream = 0x7061727469636c65;  // the particles' draws, apart from the robot's

// The run's set-up, checked.
struct Setup {
  std::string world_name;
  loc::WallMap map;
  loc::WallSensor sensor;
  std::size_t start = 0;           // index
  std::vector<std::size_t> moves;  // sides; empty: the right-hand rule
  bool moves_given = false;
  const DemoLocalizeInput *in = nullptr;
};

std::vector<std::size_t> parse_moves(const std::string &text) {
  std::vector<std::size_t> sides;
  std::size_t item = 0;
  for (std::size_t from = 0; from <= text.size(); ++item) {
    std::size_t comma = text.find(',', from);
    if (comma == std::string::npos) comma = text.size();
    std::string word = text.substr(from, comma - from);
    std::erase(word, ' ');
    const std::size_t at = word.size() == 1 ? std::string_view("NESWnesw").find(word[0]) : std::string::npos;
    const std::size_t side = at == std::string::npos ? at : at % 4;
    common::require_input(side != std::string::npos,
                    fmt::format("--moves item {} must be N, E, S or W (got '{}')", item + 1, word));
    sides.push_back(side);
    from = comma + 1;
  }
  return sides;
}

void check_numbers(const DemoLocalizeInput &in) {
  loc::validate_motion(in.motion);
  loc::validate_localized(in.localized);
  common::require_input(in.max_steps >= 0 && in.max_steps <= 100000,
                  fmt::format("--max-steps must be in [0, 100000] (got {})", in.max_steps));
  if (in.particles) {
    common::require_input(*in.particles >= 1 && *in.particles <= kMaxParticles,
                    fmt::format("--particles must be in [1, {}] (got {})", kMaxParticles, *in.particles));
    common::require_input(!in.explain, "--explain works a grid correction by hand; it does not apply with --particles");
  }
}

Setup setup_of(const DemoLocalizeInput &in) {
  check_numbers(in);
  Setup s;
  s.in = &in;
  const maze::World world = maze::load_world(world_argument(in.world.empty() ? kLocalizeWorld : in.world));
  const maze::Maze &maze = world.maze();
  common::require_input(static_cast<std::size_t>(maze.width() * maze.height()) <= kMaxCells,
                  fmt::format("demo localize prints every cell at every step: a maze of at most {} cells (got {} x {})",
                              kMaxCells, maze.width(), maze.height()));
  s.world_name = world.name();
  s.map = loc::wall_map(maze);
  s.sensor = loc::parse_sensor(in.sensor);
  s.start = loc::cell_index(s.map, maze.start());
  if (in.start) {
    common::require_input(*in.start >= 1 && static_cast<std::size_t>(*in.start) <= s.map.cells(),
                    fmt::format("--start must be a cell number from 1 to {} (got {})", s.map.cells(), *in.start));
    s.start = static_cast<std::size_t>(*in.start - 1);
  }
  s.moves_given = !in.moves.empty();
  if (s.moves_given) s.moves = parse_moves(in.moves);
  return s;
}

// The robot itself: where it is, which way it faces, what it has done.
struct Robot {
  std::size_t cell = 0;
  std::size_t heading = 0;  // N 0, E 1, S 2, W 3
  std::vector<std::size_t> commands;
  std::vector<loc::Reading> readings;
};

// The next move: --moves' next, or the right-hand rule; nothing when the moves ran out.
std::optional<std::size_t> next_move(const Setup &s, const Robot &r) {
  if (s.moves_given) {
    if (r.commands.size() >= s.moves.size()) return std::nullopt;
    return s.moves[r.commands.size()];
  }
  for (const std::size_t turn : {std::size_t{1}, std::size_t{0}, std::size_t{3}, std::size_t{2}}) {
    const std::size_t side = (r.heading + turn) % 4;
    if (!s.map.walls[r.cell][side]) return side;
  }
  return std::nullopt;  // a cell walled all round
}

// Moves the robot (with rng: failing with 1 - p); the words saying what happened.
std::string move_robot(const Setup &s, Robot &r, std::size_t side, common::Rng *rng) {
  r.commands.push_back(side);
  r.heading = side;
  const std::size_t from = r.cell;
  if (s.map.walls[from][side]) return fmt::format("a wall: the robot stays in cell {}", from + 1);
  if (rng != nullptr && !(rng->uniform01() < s.in->motion)) return fmt::format("the move failed: the robot stays in cell {}", from + 1);
  r.cell = s.map.neighbour(from, side);
  return fmt::format("the robot goes from cell {} to cell {}", from + 1, r.cell + 1);
}

// A step's move: the side chosen, the robot moved (with rng: failing with 1 - p) and the move
// written to `text`; nullopt, with "no move left", when there is none.
std::optional<std::size_t> take_move(const Setup &s, Robot &r, common::Rng *rng, std::string &text) {
  const std::optional<std::size_t> side = next_move(s, r);
  if (!side) {
    text += "no move left\n";
    return std::nullopt;
  }
  text += fmt::format("move: {} ({})\n", "NESW"[*side], move_robot(s, r, *side, rng));
  return side;
}

// The starts from which the robot's moves, every one succeeding, read the walls it read.
std::vector<int> alike_starts(const loc::WallMap &map, const Robot &r) {
  std::vector<int> alike;
  for (std::size_t start = 0; start < map.cells(); ++start) {
    std::size_t at = start;
    bool same = map.walls[at] == r.readings[0];
    for (std::size_t k = 0; same && k < r.commands.size(); ++k) {
      if (!map.walls[at][r.commands[k]]) at = map.neighbour(at, r.commands[k]);
      same = map.walls[at] == r.readings[k + 1];
    }
    if (same) alike.push_back(static_cast<int>(start) + 1);
  }
  return alike;
}

std::string header(const Setup &s, const char *filter) {
  const DemoLocalizeInput &in = *s.in;
  std::string out = fmt::format("{} localization in {}: {} x {} cells numbered row by row from the north-west (1 to {})\n",
                                filter, s.world_name, s.map.width, s.map.height, s.map.cells());
  out += model_lines(s.sensor, in.motion);
  out += fmt::format("the robot starts in cell {}{} facing north and knows which way north is; it moves {}\n", s.start + 1,
                     in.start ? "" : " (the world's start)",
                     s.moves_given ? "as --moves says" : "by the right-hand rule (right if open, else ahead, else left, else back)");
  out += in.seed ? fmt::format("seed {}: a move fails with {:g}, each side is read through the sensor model\n", *in.seed, 1.0 - in.motion)
                 : "no seed: every move succeeds and every reading is exact\n";
  out += fmt::format("localized when one cell holds at least {:g} of the {}; at most {} moves\n\n", in.localized,
                     in.particles ? "particles" : "belief", in.max_steps);
  return out + loc::numbered_map(s.map);
}

std::pair<int, double> most_likely(const std::vector<double> &belief) {
  const auto best = std::max_element(belief.begin(), belief.end());
  return {static_cast<int>(best - belief.begin()) + 1, *best};
}

// How the run ended, in one paragraph; fills result.
std::string ending(const Setup &s, const Robot &r, bool ran_out, LocalizeResult &result) {
  result.moves = static_cast<int>(r.commands.size());
  result.true_cell = static_cast<int>(r.cell) + 1;
  if (result.localized) {
    return fmt::format("localized after {} moves: cell {} holds {:.3f}; the robot is in cell {}{}\n", result.moves,
                       result.believed_cell, result.believed_share, result.true_cell,
                       result.believed_cell == result.true_cell ? "" : " (a wrong cell: the moves or readings were noisy)");
  }
  std::string out = fmt::format("not localized after {} moves ({}): most likely cell {} ({:.3f}); the robot is in cell {}\n",
                                result.moves, ran_out ? "the moves ran out" : "--max-steps", result.believed_cell,
                                result.believed_share, result.true_cell);
  if (!s.in->seed) {
    result.alike_starts = alike_starts(s.map, r);
    if (result.alike_starts.size() > 1) {
      std::string cells;
      for (const int c : result.alike_starts) cells += (cells.empty() ? "" : ", ") + std::to_string(c);
      out += fmt::format("the walls seen so far do not tell these starts apart (symmetric places: the same moves read "
                         "the same walls from each): cells {}\n", cells);
    }
  }
  return out;
}

DemoLocalizeOutput run_grid(const Setup &s) {
  std::unique_ptr<common::Rng> rng = s.in->seed ? std::make_unique<common::Rng>(*s.in->seed) : nullptr;
  Robot r{s.start, 0, {}, {}};
  std::vector<double> belief(s.map.cells(), 1.0 / static_cast<double>(s.map.cells()));
  DemoLocalizeOutput o;
  o.text = header(s, "grid Bayes filter");
  bool ran_out = false;
  for (int step = 0;; ++step) {
    o.text += fmt::format("\nstep {}\n", step);
    if (step > 0) {
      const std::optional<std::size_t> side = take_move(s, r, rng.get(), o.text);
      if (!side) {
        ran_out = true;
        break;
      }
      belief = loc::predict(s.map, belief, *side, s.in->motion);
      o.text += "after prediction:\n" + loc::belief_grid(s.map, belief);
    }
    r.readings.push_back(loc::read_walls(s.map, s.sensor, r.cell, rng.get()));
    o.text += "reading: " + loc::reading_words(r.readings.back()) + "\n";
    if (step == 0 && s.in->explain) o.text += correction_by_hand(s.map, s.sensor, belief, r.readings.back());
    belief = loc::correct(s.map, s.sensor, belief, r.readings.back());
    const auto [cell, share] = most_likely(belief);
    o.result.believed_cell = cell, o.result.believed_share = share;
    o.text += "after correction:\n" + loc::belief_grid(s.map, belief) + fmt::format("most likely: cell {} ({:.3f})\n", cell, share);
    o.result.localized = share >= s.in->localized;
    if (o.result.localized || step >= s.in->max_steps) break;
  }
  o.text += "\n";
  o.text += ending(s, r, ran_out, o.result);
  return o;
}

DemoLocalizeOutput run_particles(const Setup &s) {
  const std::uint64_t seed = s.in->seed.value_or(1);
  std::unique_ptr<common::Rng> robot_rng = s.in->seed ? std::make_unique<common::Rng>(seed) : nullptr;
  common::Rng rng(seed ^ kParticleStream);
  const int n = *s.in->particles;
  Robot r{s.start, 0, {}, {}};
  loc::Particles particles = loc::scatter(n, s.map.cells(), rng);
  DemoLocalizeOutput o;
  o.text = header(s, fmt::format("particle filter ({} particles, seed {})", n, seed).c_str());
  o.text += "\nparticles scattered uniformly:\n" + loc::count_grid(s.map, particles.counts(s.map.cells()));
  bool ran_out = false;
  for (int step = 0;; ++step) {
    o.text += fmt::format("\nstep {}\n", step);
    if (step > 0) {
      const std::optional<std::size_t> side = take_move(s, r, robot_rng.get(), o.text);
      if (!side) {
        ran_out = true;
        break;
      }
      loc::move(particles, s.map, *side, s.in->motion, rng);
      o.text += "after motion:\n" + loc::count_grid(s.map, particles.counts(s.map.cells()));
    }
    r.readings.push_back(loc::read_walls(s.map, s.sensor, r.cell, robot_rng.get()));
    o.text += "reading: " + loc::reading_words(r.readings.back()) + "\n";
    loc::resample(particles, s.map, s.sensor, r.readings.back(), rng);
    const std::vector<int> counts = particles.counts(s.map.cells());
    const auto best = std::max_element(counts.begin(), counts.end());
    o.result.believed_cell = static_cast<int>(best - counts.begin()) + 1;
    o.result.believed_share = static_cast<double>(*best) / n;
    o.text += "after resampling by P(z|cell):\n" + loc::count_grid(s.map, counts) +
              fmt::format("most particles: cell {} ({} of {}, {:.3f})\n", o.result.believed_cell, *best, n, o.result.believed_share);
    o.result.localized = o.result.believed_share >= s.in->localized;
    if (o.result.localized || step >= s.in->max_steps) break;
  }
  o.text += "\n";
  o.text += ending(s, r, ran_out, o.result);
  return o;
}

}  // namespace

DemoLocalizeOutput run_demo_localize(const DemoLocalizeInput &input) {
  const Setup s = setup_of(input);
  return input.particles ? run_particles(s) : run_grid(s);
}

}  // namespace app::course
