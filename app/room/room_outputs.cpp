// The room run's outputs (app/room/room_outputs.hpp).

#include "app/room/room_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/report/outputs.hpp"
#include "common/atomic_file.hpp"

namespace app {
namespace {

char arrow_of(double yaw_rad) {
  const double a = std::fmod(std::fmod(yaw_rad, 2 * std::numbers::pi) + 2 * std::numbers::pi, 2 * std::numbers::pi);
  const int q = static_cast<int>(std::lround(a / (std::numbers::pi / 2))) % 4;
  return ">^<v"[q];
}

}  // namespace

std::string room_ascii_map(const robot::RoomController &c, double threshold) {
  const sensing::RoomMap &map = c.map();
  std::vector<char> on_path(map.size(), 0);
  for (const std::size_t p : c.path()) on_path[p] = 1;
  const auto robot = map.cell_at(c.position());
  std::string out;
  out.reserve(map.size() + static_cast<std::size_t>(map.cells_y()));
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) {
      const std::size_t n = map.index({i, j});
      char ch = ' ';
      if (robot && robot->i == i && robot->j == j) {
        ch = arrow_of(c.yaw_rad());
      } else if (on_path[n] != 0) {
        ch = '*';
      } else if (!map.unobserved_at(n)) {
        ch = map.log_odds_at(n) >= threshold ? 'W' : '.';
      }
      out += ch;
    }
    out += '\n';
  }
  return out;
}

std::string room_binary_map(const sensing::RoomMap &map, double threshold) {
  std::string out;
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) out += map.log_odds({i, j}) >= threshold ? '1' : '0';
    out += '\n';
  }
  return out;
}

std::string room_wave_numbers(const sensing::RoomMap &map, const std::vector<std::int32_t> &wave) {
  if (wave.empty()) return "";
  const std::int32_t top = *std::max_element(wave.begin(), wave.end());
  const int width = static_cast<int>(fmt::format("{}", top).size()) + 1;
  std::string out;
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) out += fmt::format("{:>{}}", wave[map.index({i, j})], width);
    out += '\n';
  }
  return out;
}

void write_room_outputs(const std::string &dir, const sensing::RoomMap &map, const std::string &trace,
                        const std::string &summary_json, double threshold, const std::vector<RoomFile> &pictures) {
  std::ostringstream csv;
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) csv << (i == 0 ? "" : ",") << fmt::format("{:.6f}", map.log_odds({i, j}));
    csv << '\n';
  }
  std::string pgm = fmt::format("P5\n{} {}\n255\n", map.cells_x(), map.cells_y());
  const auto l0 = static_cast<float>(map.model().prior_log_odds());
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) {
      pgm += static_cast<char>(pgm_pixel(static_cast<float>(map.log_odds({i, j})), l0));
    }
  }
  const std::filesystem::path d(dir);
  common::write_file_atomically((d / "trace.csv").string(), trace);
  common::write_file_atomically((d / "logodds.csv").string(), csv.str());
  common::write_file_atomically((d / "thresholded.txt").string(), room_binary_map(map, threshold));
  common::write_file_atomically((d / "map.pgm").string(), pgm);
  common::write_file_atomically((d / "map.yaml").string(), map_yaml(map.geometry(), "map.pgm"));
  for (const RoomFile &f : pictures) {
    const std::filesystem::path path = d / f.name;
    std::filesystem::create_directories(path.parent_path());
    common::write_file_atomically(path.string(), f.bytes);
  }
  common::write_file_atomically((d / "summary.json").string(), summary_json);
}

std::string room_summary_text(const RoomRunOptions &options, const std::string &robot_name,
                              const sensing::SetUp &setup, const sensing::RoomGridSpec &spec, const RoomSummary &summary) {
  return fmt::format(
      "world         {}\nstrategy      {}\nrobot         {} ({} set-up)\ngrid          {} x {} cells of {:g} m over "
      "{:g},{:g},{:g},{:g}\nsteps         {}\nsim time      {:.2f} s\nending       {}: {}\ncells right   {} of {} "
      "({:.1f} %); observed {} of {}\nobserved      {:.2f} % of the reachable free area ({} of {} cells)\nwall time   "
      "  {:.0f} ms\n",
      options.world, robot::to_string(options.room.strategy), robot_name, setup.name, spec.cells_x, spec.cells_y,
      spec.cell_m, spec.boundary.x_start_m, spec.boundary.x_end_m, spec.boundary.y_start_m, spec.boundary.y_end_m,
      summary.steps, summary.sim_time_s, robot::to_string(summary.ending), summary.message, summary.cells_right,
      summary.cells_total, 100.0 * static_cast<double>(summary.cells_right) / static_cast<double>(summary.cells_total),
      summary.observed_cells_right, summary.observed_cells, 100.0 * summary.observed_share(),
      summary.reachable_free_observed, summary.reachable_free, summary.wall_time_ms);
}

std::string room_summary_json(const RoomRunOptions &options, const std::string &robot_name,
                              const sensing::SetUp &setup, const sensing::RoomGridSpec &spec, const RoomSummary &summary) {
  nlohmann::ordered_json j;
  j["world"] = options.world;
  j["strategy"] = robot::to_string(options.room.strategy);
  j["robot"] = robot_name;
  j["model"] = setup.name;
  j["cells_x"] = spec.cells_x;
  j["cells_y"] = spec.cells_y;
  j["cell_m"] = spec.cell_m;
  j["boundary_m"] = {spec.boundary.x_start_m, spec.boundary.x_end_m, spec.boundary.y_start_m, spec.boundary.y_end_m};
  j["steps"] = summary.steps;
  j["sim_time_s"] = summary.sim_time_s;
  j["ending"] = robot::to_string(summary.ending);
  j["message"] = summary.message;
  j["cells_right"] = summary.cells_right;
  j["cells_total"] = summary.cells_total;
  j["observed_cells"] = summary.observed_cells;
  j["observed_cells_right"] = summary.observed_cells_right;
  j["reachable_free"] = summary.reachable_free;
  j["reachable_free_observed"] = summary.reachable_free_observed;
  return j.dump(2) + "\n";
}

}  // namespace app
