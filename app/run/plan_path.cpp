#include "app/run/plan_path.hpp"

#include <ostream>
#include <vector>

#include <fmt/format.h>

#include "plan/cell/wavefront.hpp"
#include "render/ascii_map.hpp"

namespace app {

PlanSummary plan_path(const RunOptions &options, const robot::RunResult &result,
                      const mapping::SensorModel &model, render::MapStyle style, std::ostream &out) {
  PlanSummary p;
  p.from = options.plan.from.value_or(result.path.back());
  p.to = *options.plan.to;
  p.dilate = options.plan.wavefront.dilate;
  const auto path = plan::wavefront(result.grid, model, p.from, p.to, options.plan.wavefront);
  if (!path) {
    out << fmt::format("no path from ({},{}) to ({},{}) on the learned map\n\n", p.from.x, p.from.y,
                       p.to.x, p.to.y);
    return p;
  }
  p.found = true;
  p.length_subcells = path->length_subcells;
  p.length_cells = path->length_cells;
  p.path = path->subcells;
  const std::vector<bool> mask = plan::path_mask(result.grid, *path);
  style.path = &mask;
  out << fmt::format("planned path ({},{}) -> ({},{}):\n", p.from.x, p.from.y, p.to.x, p.to.y);
  out << render::render_map(result.grid, result.visits, style) << '\n';
  return p;
}

}  // namespace app
