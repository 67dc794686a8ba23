// maze_mapper run [WORLD] [options]: explore and map one world (see app/run.hpp), and the
// commands built on a run: compare (several K side by side) and plan (wavefront on the
// learned map).

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/run.hpp"
#include "app/profile_json.hpp"
#include "app/run_cli.hpp"
#include "app/terminal.hpp"
#include "commands.hpp"
#include "common/error.hpp"
#include "maze/world.hpp"
#include "model_options.hpp"

namespace app {
namespace {

// What only `run` takes, besides the mapping options.
struct RunOnlyInput {
  std::string out;
  bool no_color = false;
  bool animate = false;
  double fps = RunOptions{}.fps;
  double speed = RunOptions{}.speed;
  bool step = false;
};

void check_positive(const char *option, double value) {
  if (!(value > 0.0 && value <= 1e6)) {
    throw common::InputError(fmt::format("{} must be a number above 0 (got {})", option, value));
  }
}

// "X,Y" -> cell; throws common::InputError naming the option.
std::optional<mapping::Cell> parse_cell(const std::string &text, const char *option) {
  if (text.empty()) return std::nullopt;
  int x = 0;
  int y = 0;
  char comma = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%d %c %d %c", &x, &comma, &y, &extra) != 3 || comma != ',') {
    throw common::InputError(fmt::format("{} must be X,Y (got '{}')", option, text));
  }
  return mapping::Cell{x, y};
}

// "X,Y" (whole numbers, blanks around them allowed), or nothing.
std::optional<maze::Cell> cell_of(std::string_view text) {
  const auto integer = [](std::string_view t, int &value) {
    while (!t.empty() && t.front() == ' ') t.remove_prefix(1);
    while (!t.empty() && t.back() == ' ') t.remove_suffix(1);
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    return !t.empty() && ec == std::errc() && end == t.data() + t.size();
  };
  const std::size_t comma = text.find(',');
  maze::Cell c;
  if (comma == std::string_view::npos || !integer(text.substr(0, comma), c.x) ||
      !integer(text.substr(comma + 1), c.y)) {
    return std::nullopt;
  }
  return c;
}

std::optional<maze::Side> heading_of(std::string_view text) {
  constexpr std::pair<char, maze::Side> kHeadings[] = {
      {'N', maze::Side::north}, {'E', maze::Side::east}, {'S', maze::Side::south}, {'W', maze::Side::west}};
  for (const auto &[letter, side] : kHeadings) {
    if (text.size() == 1 && std::toupper(static_cast<unsigned char>(text[0])) == letter) return side;
  }
  return std::nullopt;
}

// --start X,Y[,HEADING]: the cell, and the heading (north unless given).
void parse_start(const std::string &text, maze::WorldOverrides &o) {
  const std::size_t second = text.find(',', text.find(',') + 1);
  o.start = cell_of(std::string_view(text).substr(0, second));
  if (second != std::string::npos) {
    const std::optional<maze::Side> heading = heading_of(std::string_view(text).substr(second + 1));
    if (heading) o.start_heading = *heading;
    if (!heading) o.start.reset();
  }
  if (!o.start) {
    throw common::InputError(
        fmt::format("--start must be X,Y or X,Y,HEADING with HEADING N, E, S or W (got '{}')", text));
  }
}

// --goal X,Y[;X,Y...]
std::vector<maze::Cell> parse_goals(const std::string &text) {
  std::vector<maze::Cell> goals;
  std::string_view rest(text);
  for (;;) {
    const std::size_t semicolon = rest.find(';');
    const std::optional<maze::Cell> goal = cell_of(rest.substr(0, semicolon));
    if (!goal) throw common::InputError(fmt::format("--goal must be X,Y or a list X,Y;X,Y;... (got '{}')", text));
    goals.push_back(*goal);
    if (semicolon == std::string_view::npos) return goals;
    rest.remove_prefix(semicolon + 1);
  }
}

}  // namespace

void add_cell_size_option(CLI::App &command, WorldInput &input) {
  command.add_option("--cell-size", input.cell_size,
                     "M: cell side of a text or num world, metres (default 1; an XML world has its own)");
}

void add_world_options(CLI::App &command, WorldInput &input) {
  add_cell_size_option(command, input);
  command.add_option("--start", input.start, "X,Y[,HEADING]: start cell, facing N, E, S or W (default N)");
  command.add_option("--goal", input.goal, "X,Y[;X,Y...]: goal cells, in place of the world's");
}

maze::WorldOverrides to_world_overrides(const WorldInput &input) {
  maze::WorldOverrides o;
  if (input.cell_size) {
    const double m = *input.cell_size;
    if (!(m > maze::kMinCellSize_m && m <= maze::kMaxCellSize_m)) {
      throw common::InputError(fmt::format(
          "--cell-size must be more than {} m (four walls of {} m) and at most {} m (got {})", maze::kMinCellSize_m,
          maze::kDefaultWallThickness_m, maze::kMaxCellSize_m, m));
    }
    o.cell_size_m = m;
  }
  if (!input.start.empty()) parse_start(input.start, o);
  if (!input.goal.empty()) o.goals = parse_goals(input.goal);
  return o;
}

void add_mapping_run_options(CLI::App &run, RunInput &input) {
  run.add_option("--subcells", input.subcells, "K: sub-cells per cell side, odd, 3 to 9 (default 3)");
  run.add_option("--model", input.model,
                 "mapping model: cell (default), ray (lidar); bump (bumpers); depth, pie, cone (range sensors)");
  run.add_option("--threshold", input.threshold,
                 "L: a sub-cell is occupied when its log-odds >= L (map, walls; default: > 0)");
  run.add_option("--pie-beta", input.pie_beta_deg, "pie model: slice half-angle, degrees (default 10)");
  run.add_option("--pie-alpha", input.pie_alpha_m, "pie model: contact slice length, m (default 0.1)");
  run.add_option("--hit-depth", input.hit_depth, "ray model: sub-cells behind a hit also occupied (default 0)");
  run.add_flag("--ignore-no-return", input.ignore_no_return,
               "ray model: a beam with no return frees nothing (default: free up to max range)");
  run.add_option("--strategy", input.strategy,
                 "dfs (default), frontier, left-wall, right-wall or floodfill");
  run.add_option("--robot", input.robot,
                 "NAME or FILE.json: robot profile (`maze_mapper robot` lists them; default: hambot, "
                 "bumper-depth for bump and depth, ir-ring for pie and cone)");
  run.add_option("--seed", input.seed, "seed of the sensor noise (default 42)")
      ->check(CLI::Validator(
          [](std::string &text) {
            // CLI11 would read "-1" as 2^64 - 1.
            return text.find('-') == std::string::npos
                       ? std::string()
                       : "must be a whole number from 0 (got '" + text + "')";
          },
          ""));
  run.add_option("--noise", input.noise,
                 "lidar noise, standard deviation as a fraction of max range (0: off; default: the robot's)");
  add_model_options(run, input.sensor);
  add_clamp_option(run, input.sensor);
  run.add_option("--max-steps", input.max_steps, "stop after this many control steps (default 1000 a cell of the maze, at least 100000)");
  run.add_option("--dilate", input.dilate, "planning: grow obstacles by N sub-cells (default 0)");
  run.add_option("--dropout", input.dropout, "fault: fraction of lidar beams that read +infinity (default 0)");
  run.add_option("--spikes", input.spikes, "fault: fraction of lidar beams that read a random range (default 0)");
  run.add_option("--stuck-bumper", input.stuck_bumper, "fault: NAME, a bumper that always reads pressed");
  run.add_option("--wheel-slip", input.wheel_slip,
                 "fault: fraction of wheel turning that does not move the robot; encoders count it all (default 0)");
  add_world_options(run, input.world_input);
}

RunOptions to_run_options(const RunInput &input) {
  RunOptions o;
  o.world = input.world;
  o.world_overrides = to_world_overrides(input.world_input);
  o.subcells = input.subcells;
  o.model = sensing::parse_model(input.model);
  o.hit_depth = input.hit_depth;
  o.ignore_no_return = input.ignore_no_return;
  if (input.threshold && !std::isfinite(*input.threshold)) {
    throw common::InputError(fmt::format("--threshold must be a finite log-odds value (got {})", *input.threshold));
  }
  o.threshold = input.threshold;
  o.range_model.pie_half_angle_rad = input.pie_beta_deg * std::numbers::pi / 180.0;
  o.range_model.pie_contact_m = input.pie_alpha_m;
  sensing::validate(o.range_model);
  o.strategy = explore::parse_strategy(input.strategy);
  o.robot = input.robot.empty() ? std::string(default_robot(o.model)) : input.robot;
  resolve_robot(o.robot);  // a bad profile file fails here, before any world is read
  o.seed = input.seed;
  if (input.noise && !(*input.noise >= 0.0 && *input.noise <= 1.0)) {
    throw common::InputError(
        fmt::format("--noise must be a fraction of the max range from 0 to 1 (got {})", *input.noise));
  }
  o.noise = input.noise;
  o.sensor = to_sensor_model_options(input.sensor);
  mapping::validate(o.sensor);
  o.ascii = input.ascii;
  if (!input.unknown.empty()) {
    if (input.unknown.size() != 1 || static_cast<unsigned char>(input.unknown[0]) < 0x20 ||
        static_cast<unsigned char>(input.unknown[0]) > 0x7e || input.unknown == "W") {
      throw common::InputError(fmt::format(
          "--unknown must be one printable ASCII character other than W (got '{}')", input.unknown));
    }
    o.unknown = input.unknown[0];
  }
  o.quiet = input.quiet;
  if (input.max_steps && *input.max_steps < 1) {
    throw common::InputError(fmt::format("--max-steps must be at least 1 (got {})", *input.max_steps));
  }
  o.max_steps = input.max_steps;
  o.plan_from = parse_cell(input.plan_from, "--from");
  o.plan_to = parse_cell(input.plan_to, input.plan_from.empty() ? "--plan-to" : "--to");
  o.dilate = input.dilate;
  o.speed_run = input.speed_run;
  o.dropout = input.dropout;
  o.spikes = input.spikes;
  o.stuck_bumper = input.stuck_bumper;
  o.wheel_slip = input.wheel_slip;
  return o;
}

std::string default_world() {
  const std::string relative = "worlds/lab4x4.txt";
  if (std::filesystem::exists(relative)) return relative;
  return std::string(MAZE_MAPPER_WORLDS_DIR) + "/lab4x4.txt";
}

namespace {

// The options run, compare and plan share: the world, the mapping options, the map's look.
void add_exploration_options(CLI::App &command, RunInput &input) {
  command.add_option("WORLD", input.world, "maze file (default worlds/lab4x4.txt)");
  add_mapping_run_options(command, input);
  command.add_flag("--ascii", input.ascii, "heading arrows as ^ > v < instead of ↑ → ↓ ←");
  command.add_option("--unknown", input.unknown, "CHAR drawn for never-observed sub-cells (default blank)");
}

RunOptions with_default_world(RunOptions options) {
  if (options.world.empty()) options.world = default_world();
  return options;
}

// Display width of UTF-8 text: code points (the map's arrows are one column each).
std::size_t display_width(const std::string &text) {
  std::size_t n = 0;
  for (const char ch : text) n += (static_cast<unsigned char>(ch) & 0xC0) != 0x80 ? 1 : 0;
  return n;
}

std::vector<std::string> split_lines(const std::string &text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    lines.push_back(text.substr(start, end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return lines;
}

// compare: one quiet run per K, printed as columns (map, blank line, summary).
// Runs the world at each K and prints the columns side by side. Ctrl-C stops the run in
// flight at its next step and the rest are not started: nothing is printed but one line,
// and the status is 130.
int compare_runs(const RunInput &input, const std::string &subcells, std::ostream &out) {
  std::vector<int> ks;
  for (const std::string &part : split_lines([&] {
         std::string t = subcells;
         for (char &ch : t) ch = ch == ',' ? '\n' : ch;
         return t;
       }())) {
    char *end = nullptr;
    const long k = std::strtol(part.c_str(), &end, 10);
    if (part.empty() || *end != '\0') {
      throw common::InputError(fmt::format("--subcells must be a list like 3,5 (got '{}')", subcells));
    }
    ks.push_back(static_cast<int>(k));
  }
  std::vector<RunOptions> runs;
  for (const int k : ks) {
    RunInput one = input;
    one.subcells = k;
    runs.push_back(with_default_world(to_run_options(one)));
  }
  std::vector<std::vector<std::string>> columns;
  std::vector<std::size_t> widths;
  int status = 0;
  double total_ms = 0.0;
  RunControls controls;
  controls.interrupted = &SigintGuard::interrupted;
  const SigintGuard sigint;
  for (const RunOptions &options : runs) {
    std::ostringstream text;
    const RunSummary summary = run_world(options, text, controls);
    if (summary.interrupted) {
      out << "compare: interrupted by Ctrl-C\n";
      return exit_status(summary);
    }
    status = std::max(status, exit_status(summary));
    // The wall time varies from run to run: one total line at the end keeps columns stable.
    std::vector<std::string> lines = split_lines(text.str());
    std::erase_if(lines, [](const std::string &l) { return l.starts_with("wall_time_ms: "); });
    total_ms += summary.wall_time_ms;
    columns.push_back(std::move(lines));
    std::size_t width = 0;
    for (const std::string &line : columns.back()) width = std::max(width, display_width(line));
    widths.push_back(width);
  }
  std::size_t rows = 0;
  for (const auto &column : columns) rows = std::max(rows, column.size());
  for (std::size_t r = 0; r < rows; ++r) {
    std::string line;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::string cell = r < columns[c].size() ? columns[c][r] : std::string();
      line += cell;
      if (c + 1 < columns.size()) line += std::string(widths[c] - display_width(cell) + 3, ' ');
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out << line << '\n';
  }
  out << fmt::format("wall_time_ms: {:.0f}\n", total_ms);
  return status;
}

}  // namespace

void add_run_command(CLI::App &cli, CommandContext &context) {
  auto input = std::make_shared<RunInput>();
  auto only = std::make_shared<RunOnlyInput>();
  CLI::App *run = cli.add_subcommand(
      "run", "explore a world cell by cell and map it; print the map as it goes and a summary");
  add_exploration_options(*run, *input);
  run->add_flag("--quiet", input->quiet, "print only the final map and the summary");
  run->add_flag("--speed-run", input->speed_run,
                "after exploring, drive the wavefront path on the learned map back to the start (with floodfill: a micromouse speed run)");
  run->add_option("--plan-to", input->plan_to,
                  "X,Y: after the run, plan (wavefront) from where the robot ended to this cell");
  run->add_option("--out", only->out,
                  "DIR: write map.pgm + map.yaml (ROS map_server), map.png, summary.json, trace.csv");
  run->add_flag("--no-color", only->no_color, "no ANSI colours (default: colours when stdout is a terminal)");
  run->add_flag("--animate", only->animate, "redraw the map in place as the robot moves");
  run->add_option("--fps", only->fps, "--animate: frames per second, at most (default 30)");
  run->add_option("--speed", only->speed,
                  "--animate: simulated seconds per wall-clock second (default 10)");
  run->add_flag("--step", only->step, "stop after each cell: Enter goes on, q quits");
  run->callback([input, only, &context] {
    RunOptions options = with_default_world(to_run_options(*input));
    if (context.run_parse_only != nullptr) {
      *context.run_parse_only = options;
      return;
    }
    check_positive("--fps", only->fps);
    check_positive("--speed", only->speed);
    options.out_dir = only->out;
    options.color = !only->no_color && is_terminal(STDOUT_FILENO);
    options.animate = only->animate;
    options.fps = only->fps;
    options.speed = only->speed;
    options.step = only->step;
    RunControls controls;
    controls.in = &std::cin;
    if (options.step && is_terminal(STDIN_FILENO)) controls.prompt = &std::cerr;
    controls.interrupted = &SigintGuard::interrupted;
    controls.terminal_fd = STDOUT_FILENO;
    const SigintGuard sigint;
    const RunSummary summary = run_world(options, std::cout, controls);
    context.status = exit_status(summary);
  });

  auto compare_input = std::make_shared<RunInput>();
  auto compare_k = std::make_shared<std::string>("3,5");
  CLI::App *compare = cli.add_subcommand(
      "compare", "run the same world at several resolutions; maps and summaries side by side");
  add_exploration_options(*compare, *compare_input);
  compare->get_option("--subcells")->description("K1,K2,...: the resolutions to compare (default 3,5)");
  compare->get_option("--subcells")->type_name("TEXT");
  compare_input->subcells = 0;
  compare->callback([compare_input, compare_k, &context] {
    RunInput in = *compare_input;
    in.quiet = true;
    context.status = compare_runs(in, *compare_k, std::cout);
  });
  compare->remove_option(compare->get_option("--subcells"));
  compare->add_option("--subcells", *compare_k, "K1,K2,...: the resolutions to compare (default 3,5)");

  auto plan_input = std::make_shared<RunInput>();
  CLI::App *plan = cli.add_subcommand(
      "plan", "explore a world quietly, then plan a path on the learned map (wavefront) and draw it");
  add_exploration_options(*plan, *plan_input);
  plan->add_option("--from", plan_input->plan_from, "X,Y: start cell of the path (default: the maze's start)");
  plan->add_option("--to", plan_input->plan_to, "X,Y: goal cell of the path (default: the maze's first goal)");
  plan->callback([plan_input, &context] {
    RunInput in = *plan_input;
    in.quiet = true;
    RunOptions options = with_default_world(to_run_options(in));
    options.plan_only = true;
    const maze::World world = maze::load_world(options.world, options.world_overrides);
    if (!options.plan_from) options.plan_from = mapping::Cell{world.maze.start().x, world.maze.start().y};
    if (!options.plan_to) {
      if (world.maze.goals().empty()) throw common::InputError("plan: the maze has no goal; give --to X,Y");
      options.plan_to = mapping::Cell{world.maze.goals().front().x, world.maze.goals().front().y};
    }
    RunControls controls;
    controls.interrupted = &SigintGuard::interrupted;
    const SigintGuard sigint;
    const RunSummary summary = run_world(options, std::cout, controls);
    context.status = exit_status(summary);
  });
}

RunOptions parse_run_options(int argc, const char *const *argv) {
  CLI::App cli{"maze_mapper", "maze_mapper"};
  cli.require_subcommand(0, 1);
  RunOptions options;
  CommandContext context;
  context.run_parse_only = &options;
  add_run_command(cli, context);
  cli.parse(argc, argv);
  return options;
}

}  // namespace app
