// The room run's outputs (app/room/room_outputs.hpp).

#include "app/room/room_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include <fmt/format.h>

#include "app/report/outputs.hpp"

namespace app {
namespace {

char arrow_of(double yaw_rad) {
  const double a = std::fmod(std::fmod(yaw_rad, 2 * std::numbers::pi) + 2 * std::numbers::pi, 2 * std::numbers::pi);
  const int q = static_cast<int>(std::lround(a / (std::numbers::pi / 2))) % 4;
  return ">^<v"[q];
}

}  // namespace

std::string room_ascii_map(const robot::MetricController &c, double threshold) {
  const sensing::MetricMap &map = c.map();
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

std::string room_binary_map(const sensing::MetricMap &map, double threshold) {
  std::string out;
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) out += map.log_odds({i, j}) >= threshold ? '1' : '0';
    out += '\n';
  }
  return out;
}

std::string room_wave_numbers(const sensing::MetricMap &map, const std::vector<std::int32_t> &wave) {
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

const std::vector<std::string> &room_own_names() {
  static const std::vector<std::string> names{"logodds.csv", "thresholded.txt", "wave.png"};
  return names;
}

std::string room_logodds_csv(const sensing::MetricMap &map) {
  std::ostringstream csv;
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) csv << (i == 0 ? "" : ",") << fmt::format("{:.6f}", map.log_odds({i, j}));
    csv << '\n';
  }
  return csv.str();
}

std::string room_pgm(const sensing::MetricMap &map) {
  std::string pgm = fmt::format("P5\n{} {}\n255\n", map.cells_x(), map.cells_y());
  const auto l0 = static_cast<float>(map.model().prior_log_odds());
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) {
      pgm += static_cast<char>(pgm_pixel(static_cast<float>(map.log_odds({i, j})), l0));
    }
  }
  return pgm;
}

}  // namespace app
