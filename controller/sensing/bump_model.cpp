// The bump model and the leveled update the range models share (sensing/range_models.hpp).

#include <algorithm>
#include <numbers>

#include <fmt/format.h>

#include "common/error.hpp"
#include "sensing/range_models.hpp"

namespace sensing {

using namespace mapping;  // the grid types this model marks

void validate(const RangeModelOptions &options) {
  const double right_angle = std::numbers::pi / 2.0;
  if (!(options.pie_half_angle_rad > 0.0 && options.pie_half_angle_rad < right_angle)) {
    throw common::InputError(fmt::format("--pie-beta must be more than 0 and less than 90 degrees (got {})",
                                         options.pie_half_angle_rad * 180.0 / std::numbers::pi));
  }
  if (!(options.pie_contact_m > 0.0 && options.pie_contact_m < 1e3)) {
    throw common::InputError(
        fmt::format("--pie-alpha must be a positive length in m (got {})", options.pie_contact_m));
  }
  if (!(options.pie_usable_fraction > 0.0 && options.pie_usable_fraction <= 1.0)) {
    throw common::InputError(fmt::format("the pie model's usable fraction of max range must be in (0, 1] (got {})",
                                         options.pie_usable_fraction));
  }
}

void LeveledUpdate::mark(const OccupancyGrid &grid, SubCell s, int level, double weight) {
  if (!grid.contains(s) || !(weight > 0.0)) return;
  marks_.push_back({grid.index(s), level, std::min(weight, 1.0)});
}

void LeveledUpdate::mark(const OccupancyGrid &grid, Point p, int level, double weight) {
  if (const auto s = grid.subcell_at(p)) mark(grid, *s, level, weight);
}

std::size_t LeveledUpdate::apply(OccupancyGrid &grid, const SensorModel &model) {
  std::sort(marks_.begin(), marks_.end(), [](const Mark &a, const Mark &b) {
    if (a.index != b.index) return a.index < b.index;
    if (a.level != b.level) return a.level < b.level;
    return a.weight > b.weight;
  });
  const double prior = model.options().prior;
  std::size_t updated = 0;
  for (std::size_t n = 0; n < marks_.size(); ++n) {
    if (n > 0 && marks_[n].index == marks_[n - 1].index) continue;  // a stronger mark came first
    const Mark &m = marks_[n];
    const double p = level_p_[static_cast<std::size_t>(m.level)];
    const double increment = model.increment_for(m.weight == 1.0 ? p : prior + m.weight * (p - prior));
    grid.at_index(m.index) =
        static_cast<float>(mapping::apply(grid.at_index(m.index), increment, model.options().clamp));
    ++updated;
  }
  marks_.clear();
  return updated;
}

LeveledUpdate make_bump_update() { return LeveledUpdate({kBumpOccupiedP, kBumpFreeP}); }

void mark_bumps(const OccupancyGrid &grid, Point robot, std::span<const BumpReading> bumpers,
                LeveledUpdate &update) {
  update.mark(grid, robot, 1);
  for (const BumpReading &b : bumpers) update.mark(grid, b.contact, b.pressed ? 0 : 1);
}

}  // namespace sensing
