// A run in metres' maps as text (app/run/metric/map_text.hpp).

#include "app/run/metric/map_text.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace app {
namespace {

char arrow_of(double yaw_rad) {
  const double a = std::fmod(std::fmod(yaw_rad, 2 * std::numbers::pi) + 2 * std::numbers::pi, 2 * std::numbers::pi);
  const int q = static_cast<int>(std::lround(a / (std::numbers::pi / 2))) % 4;
  return ">^<v"[q];
}

}  // namespace

std::string metric_ascii_map(const robot::MetricController &c, double threshold) {
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

std::string metric_binary_map(const sensing::MetricMap &map, double threshold) {
  std::string out;
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) out += map.log_odds({i, j}) >= threshold ? '1' : '0';
    out += '\n';
  }
  return out;
}

std::string metric_wave_numbers(const sensing::MetricMap &map, const std::vector<std::int32_t> &wave) {
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

}  // namespace app
