#include "app/course/demo_1d.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>

#include <fmt/format.h>

#include "common/error.hpp"
#include "common/random.hpp"

namespace app::course {
namespace {

// Cells that fit in [0, length]: floor(length / resolution) + 1, with a little slack so that
// 200 / 10 is 20 however the division rounds. A double, so a huge ratio cannot overflow.
double cell_count(const Demo1dOptions &options) {
  return std::floor(options.length_cm / options.resolution_cm * (1.0 + 1e-9)) + 1.0;
}

void require_distance(const char *option, double cm) {
  if (!std::isfinite(cm) || cm < 0.0) {
    throw common::InputError(
        fmt::format("{} must be a finite number of cm >= 0 (got {})", option, cm));
  }
}

void validate_geometry(const Demo1dOptions &options) {
  if (!std::isfinite(options.resolution_cm) || options.resolution_cm <= 0.0) {
    throw common::InputError(fmt::format("--resolution must be a positive number of cm (got {})",
                                         options.resolution_cm));
  }
  require_distance("--length", options.length_cm);
  require_distance("--behind", options.behind_cm);
  const double cells = cell_count(options);
  if (cells > kDemo1dMaxCells) {
    throw common::InputError(fmt::format("--length {} with --resolution {} gives {} cells (at most {})",
                                         options.length_cm, options.resolution_cm, cells,
                                         kDemo1dMaxCells));
  }
}

void validate_measurements(const std::vector<double> &measurements_cm) {
  if (measurements_cm.empty()) {
    throw common::InputError("--measurements must list at least one distance in cm");
  }
  for (std::size_t i = 0; i < measurements_cm.size(); ++i) {
    const double z = measurements_cm[i];
    if (!std::isfinite(z) || z < 0.0) {
      throw common::InputError(fmt::format(
          "--measurements item {} must be a finite number of cm >= 0 (got {})", i + 1, z));
    }
  }
}

}  // namespace

void validate(const Demo1dOptions &options) {
  mapping::validate(options.model);
  validate_geometry(options);
  validate_measurements(options.measurements_cm);
}

std::vector<double> cell_positions_cm(const Demo1dOptions &options) {
  const auto count = static_cast<std::size_t>(cell_count(options));
  std::vector<double> positions(count);
  for (std::size_t i = 0; i < count; ++i) {
    positions[i] = static_cast<double>(i) * options.resolution_cm;  // no accumulated rounding
  }
  return positions;
}

CellUpdate classify(double cell_cm, double measurement_cm, double behind_cm) {
  if (cell_cm < measurement_cm) return CellUpdate::free;
  if (cell_cm <= measurement_cm + behind_cm) return CellUpdate::occupied;
  return CellUpdate::none;
}

std::vector<Demo1dCell> integrate(const Demo1dOptions &options,
                                  std::span<const double> measurements_cm) {
  const mapping::SensorModel model(options.model);
  std::vector<Demo1dCell> cells;
  for (const double x : cell_positions_cm(options)) {
    cells.push_back(Demo1dCell{.position_cm = x, .log_odds = model.prior_log_odds()});
  }
  for (const double z : measurements_cm) {
    for (Demo1dCell &cell : cells) {
      switch (classify(cell.position_cm, z, options.behind_cm)) {
        case CellUpdate::free:
          cell.log_odds = model.update_free(cell.log_odds);
          ++cell.free_updates;
          break;
        case CellUpdate::occupied:
          cell.log_odds = model.update_occupied(cell.log_odds);
          ++cell.occupied_updates;
          break;
        case CellUpdate::none:
          break;
      }
    }
  }
  for (Demo1dCell &cell : cells) cell.belief = model.probability_of(cell.log_odds);
  return cells;
}

std::vector<double> shuffled(std::span<const double> measurements_cm, std::uint64_t seed) {
  std::vector<double> order(measurements_cm.begin(), measurements_cm.end());
  common::Rng rng(seed);
  rng.shuffle(std::span<double>(order));
  return order;
}

double max_log_odds_difference(std::span<const Demo1dCell> a, std::span<const Demo1dCell> b) {
  assert(a.size() == b.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    largest = std::max(largest, std::abs(a[i].log_odds - b[i].log_odds));
  }
  return largest;
}

}  // namespace app::course
