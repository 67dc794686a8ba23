// The room map and its marks (sensing/metric/map.hpp).

#include "sensing/metric/map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "common/error.hpp"
#include "mapping/log_odds.hpp"
#include "mapping/traversal.hpp"
#include "sensing/cone_cells.hpp"
#include "sensing/pie_slice.hpp"

namespace sensing {
namespace {

constexpr double kSquareTolerance = 1e-9;

void require_boundary(const MetricBoundary &b) {
  require_boundary_m(b.x_start_m, b.x_end_m, b.y_start_m, b.y_end_m);
}

}  // namespace

MetricGridSpec metric_grid_from_cells(const MetricBoundary &b, int cells_x, int cells_y) {
  require_boundary(b);
  common::require_input(
      cells_x >= 1 && cells_y >= 1 && cells_x <= kMaxMetricCellsPerSide && cells_y <= kMaxMetricCellsPerSide,
      fmt::format("--cells must be X,Y with each 1 to {} (got {},{})", kMaxMetricCellsPerSide, cells_x, cells_y));
  const double w = b.width_m() / cells_x;
  const double h = b.height_m() / cells_y;
  common::require_input(
      std::abs(w - h) <= kSquareTolerance * std::max(w, h),
      fmt::format("--cells {},{} over a {:g} x {:g} m boundary makes cells {:g} m wide and {:g} m high: the room "
                  "map's cells are square (try --cells {},{} or --resolution {:g})",
                  cells_x, cells_y, b.width_m(), b.height_m(), w, h, cells_x,
                  std::max(1, static_cast<int>(std::lround(b.height_m() / w))), w));
  MetricGridSpec s{b, cells_x, cells_y, w};
  return s;
}

MetricGridSpec metric_grid_from_resolution(const MetricBoundary &b, double cell_m) {
  require_boundary(b);
  common::require_input(std::isfinite(cell_m) && cell_m > 0.0,
                        fmt::format("--resolution must be > 0 m (got {})", cell_m));
  const double nx = std::ceil(b.width_m() / cell_m - 1e-9);
  const double ny = std::ceil(b.height_m() / cell_m - 1e-9);
  common::require_input(
      nx <= kMaxMetricCellsPerSide && ny <= kMaxMetricCellsPerSide,
      fmt::format("--resolution {:g} m over a {:g} x {:g} m boundary makes {:g} x {:g} cells; at most {} a side",
                  cell_m, b.width_m(), b.height_m(), nx, ny, kMaxMetricCellsPerSide));
  MetricGridSpec s;
  s.cells_x = std::max(1, static_cast<int>(nx));
  s.cells_y = std::max(1, static_cast<int>(ny));
  s.cell_m = cell_m;
  s.boundary = {b.x_start_m, b.x_start_m + s.cells_x * cell_m, b.y_start_m, b.y_start_m + s.cells_y * cell_m};
  return s;
}

std::uint64_t metric_map_bytes(const MetricGridSpec &s) {
  // a double per cell, a level byte and a marked index for a scan's marks
  const auto cells = static_cast<std::uint64_t>(s.cells_x) * static_cast<std::uint64_t>(s.cells_y);
  return cells * (sizeof(double) + 1 + sizeof(std::size_t));
}

void validate(const MetricGridSpec &s, std::uint64_t max_bytes) {
  require_boundary(s.boundary);
  common::require_input(
      s.cells_x >= 1 && s.cells_y >= 1 && s.cells_x <= kMaxMetricCellsPerSide && s.cells_y <= kMaxMetricCellsPerSide,
      fmt::format("the room map must have 1 to {} cells a side (got {} x {})", kMaxMetricCellsPerSide, s.cells_x,
                  s.cells_y));
  common::require_input(std::isfinite(s.cell_m) && s.cell_m > 0.0,
                        fmt::format("the room map's cells must be > 0 m (got {})", s.cell_m));
  const std::uint64_t bytes = metric_map_bytes(s);
  common::require_input(bytes <= max_bytes,
                        fmt::format("a {} x {} room map would take {:.1f} MiB, more than {:.0f} MiB: use a coarser "
                                    "--resolution or fewer --cells",
                                    s.cells_x, s.cells_y, static_cast<double>(bytes) / 1048576.0,
                                    static_cast<double>(max_bytes) / 1048576.0));
}

MetricMap::MetricMap(const MetricGridSpec &spec, const mapping::SensorModel &model) : spec_(spec), model_(model) {
  validate(spec_);
  geometry_.width_cells = spec_.cells_x;
  geometry_.height_cells = spec_.cells_y;
  geometry_.subcells = 1;
  geometry_.cell_size_m = spec_.cell_m;
  geometry_.origin = {spec_.boundary.x_start_m, spec_.boundary.y_start_m};
  grid_.cells_x = spec_.cells_x;
  grid_.cells_y = spec_.cells_y;
  grid_.log_odds.assign(static_cast<std::size_t>(spec_.cells_x) * static_cast<std::size_t>(spec_.cells_y),
                        model_.prior_log_odds());
  marked_occupied_.assign(grid_.log_odds.size(), false);
}

std::optional<MetricCell> MetricMap::cell_at(mapping::Point p) const {
  const double fx = std::floor((p.x_m - spec_.boundary.x_start_m) / spec_.cell_m);
  const double fy = std::floor((p.y_m - spec_.boundary.y_start_m) / spec_.cell_m);
  if (!(fx >= 0 && fy >= 0 && fx < spec_.cells_x && fy < spec_.cells_y)) return std::nullopt;
  return MetricCell{static_cast<int>(fx), static_cast<int>(fy)};
}

mapping::Point MetricMap::centre_of(MetricCell c) const {
  return {spec_.boundary.x_start_m + (c.i + 0.5) * spec_.cell_m, spec_.boundary.y_start_m + (c.j + 0.5) * spec_.cell_m};
}

BumpDepthOptions MetricMap::bump_depth_options() const {
  BumpDepthOptions o;
  o.cells_x = spec_.cells_x;
  o.cells_y = spec_.cells_y;
  o.x_start_m = spec_.boundary.x_start_m;
  o.x_end_m = spec_.boundary.x_end_m;
  o.y_start_m = spec_.boundary.y_start_m;
  o.y_end_m = spec_.boundary.y_end_m;
  o.prior = model_.options().prior;
  o.base = model_.options().base;
  return o;
}

void MetricMarks::mark(const MetricMap &map, MetricCell c, int level) {
  if (!map.contains(c)) return;
  if (level_.size() != map.size()) level_.assign(map.size(), kUnmarked);
  const std::size_t flat = map.index(c);
  const auto l = static_cast<std::uint8_t>(level);
  if (level_[flat] == kUnmarked) marked_.push_back(flat);
  level_[flat] = std::min(level_[flat], l);
}

void MetricMarks::mark(const MetricMap &map, mapping::Point p, int level) {
  if (const auto c = map.cell_at(p)) mark(map, *c, level);
}

int MetricMarks::level_of(const MetricMap &map, MetricCell c) const {
  if (!map.contains(c) || level_.size() != map.size()) return -1;
  const std::uint8_t l = level_[map.index(c)];
  return l == kUnmarked ? -1 : l;
}

void MetricMap::set_log_odds(std::size_t flat, double value) {
  const double prior = model_.prior_log_odds();
  if (value == prior && grid_.log_odds[flat] != prior) ++back_to_prior_;
  grid_.log_odds[flat] = value;
}

void MetricMap::observe_by_body(std::size_t flat) {
  if (unobserved_at(flat)) ++body_observed_;
  set_log_odds(flat, model_.update_free(grid_.log_odds[flat]));
}

void MetricMap::observe_contact(std::size_t flat) {
  marked_occupied_[flat] = true;
  set_log_odds(flat, model_.update_occupied(grid_.log_odds[flat]));
}

std::size_t MetricMarks::apply(MetricMap &map) {
  const mapping::SensorModel &model = map.model();
  const double increments[2] = {model.increment_for(level_p_[0]), model.increment_for(level_p_[1])};
  const std::vector<double> &values = map.log_grid().log_odds;
  for (const std::size_t flat : marked_) {
    map.set_log_odds(flat, mapping::apply(values[flat], increments[level_[flat]], model.options().clamp));
    if (level_[flat] == kMetricOccupied) map.marked_occupied_[flat] = true;
    level_[flat] = kUnmarked;
  }
  const std::size_t count = marked_.size();
  marked_.clear();
  return count;
}

void mark_metric_lidar(const MetricMap &map, const LidarScan &scan, MetricMarks &marks) {
  for (int n = 0; n < scan.beam_count(); ++n) {
    const ReadingKind kind = scan.kind(n);
    if (kind == ReadingKind::invalid) continue;
    const bool hit = kind == ReadingKind::hit;
    const double reach = hit ? scan.ranges[static_cast<std::size_t>(n)] : scan.max_range_m;
    const double a = scan.beam_world_angle_rad(n);
    const double dx = std::cos(a);
    const double dy = std::sin(a);
    mapping::trace_ray(map.geometry(), scan.origin, dx, dy, [&](mapping::SubCell s, double exit_m) {
      if (exit_m >= reach) return false;
      marks.mark(map, MetricCell{s.x, s.y}, kMetricFree);
      return true;
    });
    const mapping::Point end{scan.origin.x_m + reach * dx, scan.origin.y_m + reach * dy};
    marks.mark(map, end, hit ? kMetricOccupied : kMetricFree);
  }
}

void mark_metric_pie(const MetricMap &map, const RangeModelOptions &options, std::span<const RangeReading> readings,
                   MetricMarks &marks) {
  const double r = map.cell_m();
  const double x0 = map.spec().boundary.x_start_m;
  const double y0 = map.spec().boundary.y_start_m;
  for (const RangeReading &reading : readings) {
    if (!(reading.range_m >= 0.0)) continue;  // NaN: no reading
    PieSlice s;
    s.x_m = reading.origin.x_m;
    s.y_m = reading.origin.y_m;
    s.heading_deg = reading.angle_rad * 180.0 / 3.14159265358979323846;
    s.reading_m = reading.range_m;
    // A reading within two of its errors of max range saw nothing (is_no_return): the
    // sensor's noise must not make phantom contacts at max range.
    s.contact = reading.range_m < reading.max_range_m && !is_no_return(reading);
    s.clear_m = std::min(reading.range_m, reading.max_range_m);
    s.contact_m = s.contact ? s.clear_m + options.pie_contact_m : s.clear_m;
    const double reach = s.contact_m;
    const int i0 = std::max(0, static_cast<int>(std::floor((s.x_m - reach - x0) / r)) - 1);
    const int i1 = std::min(map.cells_x() - 1, static_cast<int>(std::floor((s.x_m + reach - x0) / r)) + 1);
    const int j0 = std::max(0, static_cast<int>(std::floor((s.y_m - reach - y0) / r)) - 1);
    const int j1 = std::min(map.cells_y() - 1, static_cast<int>(std::floor((s.y_m + reach - y0) / r)) + 1);
    const double half_diagonal = r * std::sqrt(0.5);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        // Cells wholly beyond the slices' reach or angle cannot hold a point of them.
        const double cx = x0 + (i + 0.5) * r - s.x_m;
        const double cy = y0 + (j + 0.5) * r - s.y_m;
        const double centre_m = std::hypot(cx, cy);
        if (centre_m - half_diagonal > reach) continue;
        if (centre_m > 2 * half_diagonal) {
          const double off = std::abs(std::remainder(std::atan2(cy, cx) - reading.angle_rad, 2 * std::numbers::pi));
          if (off - std::asin(half_diagonal / centre_m) > options.pie_half_angle_rad + 1e-9) continue;
        }
        const PieVerdict v = pie_slice_verdict(s, options.pie_half_angle_rad, x0 + i * r, y0 + j * r, r);
        if (v == PieVerdict::outside) continue;
        marks.mark(map, MetricCell{i, j}, v == PieVerdict::contact ? kMetricOccupied : kMetricFree);
      }
    }
  }
}

void mark_metric_cone(const MetricMap &map, const RangeModelOptions &, std::span<const RangeReading> readings,
                      MetricMarks &marks) {
  const double r = map.cell_m();
  for (const RangeReading &reading : readings) {
    if (!(reading.range_m >= 0.0)) continue;
    ConeReading in;
    in.x_cells = (reading.origin.x_m - map.spec().boundary.x_start_m) / r;
    in.y_cells = (reading.origin.y_m - map.spec().boundary.y_start_m) / r;
    in.phi_rad = reading.angle_rad;
    in.sigma_rad = reading.aperture_rad;
    in.eps = reading.range_error;
    const bool nothing_seen = reading.range_m >= reading.max_range_m * (1.0 - 2.0 * reading.range_error);
    if (nothing_seen) {
      if (reading.echo_can_be_lost) continue;
      const double reach_cells = reading.max_range_m * kConeNoReturnReach / r;
      in.d_cells = reach_cells;
      for (const auto &[i, j] : cone_cells_between(in, 0.0, reach_cells).cells) marks.mark(map, MetricCell{i, j}, kMetricFree);
      continue;
    }
    in.d_cells = reading.range_m / r;
    const double inner = in.d_cells * (1.0 - in.eps);
    for (const auto &[i, j] : cone_cells(in).cells) marks.mark(map, MetricCell{i, j}, kMetricOccupied);
    for (const auto &[i, j] : cone_cells_between(in, 0.0, inner - kConeRadiusInc).cells) {
      marks.mark(map, MetricCell{i, j}, kMetricFree);
    }
  }
}

}  // namespace sensing
