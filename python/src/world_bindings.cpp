// Worlds, the scorer (the run's own rules, app/run/evaluation.hpp) and the program's own run.

#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "app/run/evaluation.hpp"
#include "app/run/option_fields.hpp"
#include "app/run/profile_json.hpp"
#include "app/run/run.hpp"
#include "bindings.hpp"
#include "common/error.hpp"
#include "common/random.hpp"
#include "mapping/walls.hpp"
#include "maze/world/world.hpp"
#include "robot/cell/controller.hpp"

namespace maze_mapper_python {

namespace {

const char *verdict_words(app::SideVerdict v) {
  switch (v) {
    case app::SideVerdict::right: return "right";
    case app::SideVerdict::missed: return "a wall missed";
    case app::SideVerdict::phantom: return "a wall that is not there";
    case app::SideVerdict::unseen_opening: return "an opening never seen";
  }
  return "right";
}

// A side the scorer counts as wrong: cell, side ('N', 'E', 'S', 'W') and what is wrong.
struct ScoredSide {
  int x;
  int y;
  char side;
  std::string verdict;
};

// What score() reports: the run's coverage and wall accuracy, and every wrong side.
struct Score {
  app::MapScore map;
  std::vector<ScoredSide> wrong;        // every scored side not right, in scan order
  std::size_t wrong_where_looked = 0;   // those of cells visited (the run's "wrong map")
  std::vector<ScoredSide> first_wrong_where_looked;
};

// load_world(path, cell_size_m=..., start_position=..., random_start=..., seed=...): the cell
// size checked as --cell-size checks it (its one rule).
maze::World load(const std::string &path, std::optional<double> cell_size_m, std::optional<int> start_position,
                 bool random_start, std::uint64_t seed) {
  maze::WorldOverrides overrides;
  if (cell_size_m) {
    app::option_field<maze::WorldOverrides>("--cell-size").parse(overrides, fmt::format("{}", *cell_size_m));
  }
  overrides.start_position = start_position;
  overrides.random_start = random_start;
  overrides.random_start_seed = seed;
  return maze::load_world(path, overrides);
}

std::vector<bool> visited_cells(const explore::Visits &visits) {
  std::vector<bool> v(static_cast<std::size_t>(visits.width()) * static_cast<std::size_t>(visits.height()));
  for (int y = 0; y < visits.height(); ++y) {
    for (int x = 0; x < visits.width(); ++x) {
      v[static_cast<std::size_t>(y) * static_cast<std::size_t>(visits.width()) + static_cast<std::size_t>(x)] =
          visits.visited({x, y});
    }
  }
  return v;
}

Score score_grid(const maze::Maze &world, const mapping::OccupancyGrid &grid, const explore::Visits &visits,
                 float initial_log_odds, std::optional<float> threshold) {
  const maze::Maze truth = maze::with_solid_sides(world, grid.k());  // its solids in cells, as run scores them
  if (grid.width() != truth.width() || grid.height() != truth.height()) {
    throw common::InputError(fmt::format("the grid is {}x{} cells, the world {}x{}", grid.width(), grid.height(),
                                         truth.width(), truth.height()));
  }
  const auto side_of = [&grid, initial_log_odds, threshold](maze::Cell c, maze::Side s) {
    return mapping::side_state(grid, initial_log_odds, {c.x, c.y}, s, threshold);
  };
  const std::vector<bool> visited = visited_cells(visits);
  Score score;
  score.map = app::score_map(truth, visited, side_of);
  app::for_each_scored_side(truth, truth.reachable_from_start(), [&](maze::Cell c, maze::Side s) {
    const app::SideVerdict v = app::judge_side(truth.has_wall(c, s), side_of(c, s));
    if (v != app::SideVerdict::right) score.wrong.push_back({c.x, c.y, common::to_char(s), verdict_words(v)});
  });
  const app::WrongSides where = app::wrong_sides_where_looked(truth, visited, side_of);
  score.wrong_where_looked = where.count;
  for (const app::WrongSide &w : where.first) {
    score.first_wrong_where_looked.push_back(
        {w.cell.x, w.cell.y, common::to_char(w.side), verdict_words(w.verdict)});
  }
  return score;
}

Score score(const maze::World &world, const py::object &grid, const py::object &visited,
            std::optional<float> initial_log_odds, std::optional<float> threshold) {
  if (py::isinstance<PyGrid>(grid)) {
    const PyGrid &g = grid.cast<const PyGrid &>();
    const float initial = initial_log_odds.value_or(g.initial_log_odds());
    const explore::Visits visits = visited.is_none() ? g.visits : visits_from(visited, g.grid.width(), g.grid.height());
    return score_grid(world.maze(), g.grid, visits, initial, threshold);
  }
  const float initial = initial_log_odds.value_or(0.0f);
  const mapping::OccupancyGrid g = grid_from_array(grid, initial);
  return score_grid(world.maze(), g, visits_from(visited, g.width(), g.height()), initial, threshold);
}

// The program's own exploration of a world (`maze_mapper run`, without printing): its grid
// with its visits, and the run's numbers.
py::tuple explore_world(const maze::World &world, const std::optional<std::string> &robot_name, int subcells,
                        const std::string &model, std::uint64_t seed, std::optional<double> noise) {
  app::RunOptions options;
  options.world = world.file;
  options.subcells = subcells;
  options.model.kind = sensing::parse_model(model);
  options.robot = robot_name.value_or(std::string(app::default_robot(options.model.kind)));
  options.simulation.seed = seed;
  options.simulation.noise = noise;
  app::validate(options);
  const maze::sim::RobotProfile profile = app::resolve_robot(options.robot);
  app::require_sensors(options, profile);
  const robot::ControllerOptions controller_opts = app::controller_options(options, world.maze(), profile);
  webots::embedded::Simulation simulation(world, profile, options.simulation);
  robot::CellController controller(simulation.robot(), controller_opts);
  robot::RunResult result = controller.run();
  PyGrid grid(result.grid.geometry(), mapping::SensorModel(options.sensor));
  grid.grid = std::move(result.grid);
  grid.visits = result.search_visits.value_or(result.visits);
  py::dict run;
  run["end"] = std::string(robot::to_string(result.reason));
  run["steps"] = result.steps;
  run["moves"] = result.moves;
  run["visited"] = result.visited;
  run["sim_time_s"] = result.sim_time_s;
  return py::make_tuple(std::move(grid), run);
}

}  // namespace

void bind_world(py::module_ &m) {
  py::class_<maze::World>(m, "World",
                          "A world read from a file: a maze (walls on a cell lattice: text map, num, .maz, the "
                          "course's XML) or an arena (solids in metres: a room file, the course's XML of thick "
                          "walls). The cell properties (width ... has_wall, text) are a maze's and raise Error "
                          "on an arena; the metric ones (name ... goal_points) are any world's.")
      .def_readonly("file", &maze::World::file)
      .def_readonly("warnings", &maze::World::warnings)
      .def_property_readonly("is_maze", &maze::World::on_lattice, "Whether its walls lie on a cell lattice.")
      .def_property_readonly("name", &maze::World::name)
      .def_property_readonly("obstacles", [](const maze::World &w) { return w.geometry().obstacles.size(); },
                             "Its solids in metres, counted (a maze's walls as rectangles).")
      .def_property_readonly("boundary",
                             [](const maze::World &w) {
                               const maze::Arena g = w.geometry();
                               return py::make_tuple(g.x_min_m, g.x_max_m, g.y_min_m, g.y_max_m);
                             },
                             "(x_min, x_max, y_min, y_max), m: the floor the robot stays on.")
      .def_property_readonly("goal_points",
                             [](const maze::World &w) {
                               std::vector<std::pair<double, double>> goals;
                               for (const maze::ArenaPoint &g : w.geometry().goals) goals.emplace_back(g.x_m, g.y_m);
                               return goals;
                             },
                             "The goals in metres (a maze's goal cells' centres).")
      .def_property_readonly("landmarks",
                             [](const maze::World &w) {
                               std::vector<std::tuple<double, double, double, std::tuple<double, double, double>>> out;
                               for (const maze::ArenaDisc &d : w.geometry().discs) {
                                 if (!d.landmark) continue;
                                 out.emplace_back(d.centre_x_m, d.centre_y_m, d.landmark->height_m,
                                                  std::make_tuple(d.landmark->red, d.landmark->green, d.landmark->blue));
                               }
                               return out;
                             },
                             "The landmark cylinders it states: (x_m, y_m, height_m, (red, green, blue)).")
      .def_property_readonly("starts",
                             [](const maze::World &w) {
                               std::vector<std::tuple<double, double, double>> starts;
                               for (const maze::ArenaPose &p : w.geometry().starts) {
                                 starts.emplace_back(p.x_m, p.y_m, p.yaw_rad);
                               }
                               return starts;
                             },
                             "The start poses (x_m, y_m, yaw_rad) the world states.")
      .def_property_readonly("width", [](const maze::World &w) { return w.maze().width(); })
      .def_property_readonly("height", [](const maze::World &w) { return w.maze().height(); })
      .def_property_readonly("cell_size_m", [](const maze::World &w) { return w.maze().cell_size_m(); })
      .def_property_readonly("origin",
                             [](const maze::World &w) { return std::make_pair(w.maze().origin_x_m(), w.maze().origin_y_m()); })
      .def_property_readonly("start",
                             [](const maze::World &w) { return std::make_pair(w.maze().start().x, w.maze().start().y); })
      .def_property_readonly("start_heading",
                             [](const maze::World &w) { return std::string(1, common::to_char(w.maze().start_heading())); })
      .def_property_readonly("goals",
                             [](const maze::World &w) {
                               std::vector<std::pair<int, int>> goals;
                               for (const maze::Cell c : w.maze().goals()) goals.emplace_back(c.x, c.y);
                               return goals;
                             })
      .def(
          "has_wall",
          [](const maze::World &w, int x, int y, const std::string &side) {
            if (!w.maze().contains({x, y})) {
              throw common::InputError(
                  fmt::format("cell ({},{}) is outside the {}x{} maze", x, y, w.maze().width(), w.maze().height()));
            }
            return w.maze().has_wall({x, y}, parse_heading(side));
          },
          py::arg("x"), py::arg("y"), py::arg("side"), "Whether side N, E, S or W of cell (x, y) is walled.")
      .def(
          "text", [](const maze::World &w) { return maze::format_world(w.maze(), maze::Format::text_map, w.file); },
          "The maze as a canonical text map (what `maze_mapper show` prints).");
  m.attr("LANDMARK_RADIUS_M") = maze::kLandmarkRadius_m;  // the course's Landmark cylinders
  m.attr("MAX_ARENA_SIDE_M") = maze::kMaxArenaSide_m;  // the longest side of any world
  m.def("load_world", &load, py::arg("path"), py::kw_only(), py::arg("cell_size_m") = py::none(),
        py::arg("start_position") = py::none(), py::arg("random_start") = false,
        py::arg("seed") = common::kDefaultSeed,
        "Reads a world in any format (detected by content), validated, as `maze_mapper run` and `room` read it. "
        "cell_size_m: for text and num worlds (--cell-size), 1 m by default; start_position (1-based) or "
        "random_start (drawn with seed) choose a maze's start among its start positions (--start pos:N, random).");

  py::class_<ScoredSide>(m, "ScoredSide")
      .def_readonly("x", &ScoredSide::x)
      .def_readonly("y", &ScoredSide::y)
      .def_property_readonly("side", [](const ScoredSide &s) { return std::string(1, s.side); })
      .def_readonly("verdict", &ScoredSide::verdict)
      .def("__repr__", [](const ScoredSide &s) { return fmt::format("{} of ({},{}) {}", s.side, s.x, s.y, s.verdict); });
  py::class_<Score>(m, "Score")
      .def_property_readonly("coverage_percent", [](const Score &s) { return s.map.coverage_percent(); })
      .def_property_readonly("wall_accuracy_percent", [](const Score &s) { return s.map.wall_accuracy_percent(); })
      .def_property_readonly("reachable_cells", [](const Score &s) { return s.map.reachable_cells; })
      .def_property_readonly("visited_reachable_cells", [](const Score &s) { return s.map.visited_reachable_cells; })
      .def_property_readonly("sides", [](const Score &s) { return s.map.sides; })
      .def_property_readonly("sides_correct", [](const Score &s) { return s.map.sides_correct; })
      .def_readonly("wrong_sides", &Score::wrong)
      .def_readonly("wrong_where_looked", &Score::wrong_where_looked)
      .def_readonly("first_wrong_where_looked", &Score::first_wrong_where_looked);
  m.def("score", &score, py::arg("world"), py::arg("grid"), py::arg("visited") = py::none(), py::kw_only(),
        py::arg("initial_log_odds") = py::none(), py::arg("threshold") = py::none(),
        "Scores a grid against a world's truth as `maze_mapper run` scores its own: coverage (visited "
        "reachable cells), wall accuracy (sides of reachable cells learned right; never observed is "
        "wrong) and the sides learned wrong.");
  m.def("explore_world", &explore_world, py::arg("world"), py::kw_only(), py::arg("robot") = py::none(),
        py::arg("subcells") = 3, py::arg("model") = "cell", py::arg("seed") = common::kDefaultSeed,
        py::arg("noise") = py::none(),
        "The program's own exploration (`maze_mapper run` without printing): (grid, run) with the learned "
        "OccupancyGrid and its visits, and the run's end, steps, moves, visited cells and simulated time.");
}

}  // namespace maze_mapper_python
