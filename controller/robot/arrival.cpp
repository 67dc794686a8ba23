#include "robot/arrival.hpp"

#include <algorithm>

#include <fmt/format.h>


namespace robot {

using mapping::Cell;
using mapping::Heading;
using mapping::SideState;

Arrival::Arrival(const ControllerOptions &options, Drive &drive, Senses &senses, const mapping::OccupancyGrid &grid,
                 explore::Visits &visits, explore::WallQuery walls, std::function<std::int64_t()> steps)
    : options_(options),
      behaviour_(sensing::setup(options.model.kind).arrival),
      drive_(drive),
      senses_(senses),
      grid_(grid),
      visits_(visits),
      walls_(std::move(walls)),
      steps_(std::move(steps)) {}

Motion Arrival::arrive(Cell c, Heading &facing, bool new_cell) {
  if (const Motion s = await_revolution(); s != Motion::ok) return s;
  scan(c);
  switch (behaviour_) {
    case sensing::Arrival::resolve_and_confirm:
      if (const Motion s = resolve(c, facing); s != Motion::ok) return s;
      return confirm(c);
    case sensing::Arrival::resolve: return resolve(c, facing);
    case sensing::Arrival::probe: return probe_unknown_sides(c, facing);
    case sensing::Arrival::look_around: return new_cell ? look_around(c, facing) : Motion::ok;
  }
  return Motion::ok;
}

// A rotating lidar fills its range image a slice per step: before a scan, stays at rest for
// a whole revolution, so that every beam is read from here.
Motion Arrival::await_revolution() {
  for (int i = 0; i < senses_.revolution_steps(); ++i) {
    if (const Motion s = drive_.come_to_rest(); s != Motion::ok) return s;
  }
  return Motion::ok;
}

Motion Arrival::rest_and_scan(Cell c) {
  if (const Motion s = drive_.come_to_rest(); s != Motion::ok) return s;
  if (const Motion s = await_revolution(); s != Motion::ok) return s;
  scan(c);
  return Motion::ok;
}

bool Arrival::unknown(Cell c, Heading h) const { return walls_(c, h) == SideState::unknown; }

void Arrival::face(Cell c, Heading h, Heading &facing) {
  facing = h;
  visits_.record(c, facing);
}

Motion Arrival::rescan_while_unknown(Cell c, const std::function<bool()> &still_unknown) {
  for (int attempt = 0; attempt < options_.max_rescans && still_unknown(); ++attempt) {
    if (const Motion s = rest_and_scan(c); s != Motion::ok) return s;
  }
  return Motion::ok;
}

Motion Arrival::resolve(Cell c, Heading &facing) {
  const auto any_unknown = [&] { return std::ranges::any_of(mapping::kHeadings, [&](Heading h) { return unknown(c, h); }); };
  if (const Motion s = rescan_while_unknown(c, any_unknown); s != Motion::ok) return s;
  for (const Heading h : mapping::kHeadings) {
    if (!unknown(c, h)) continue;
    if (const Motion s = drive_.turn_to(h); s != Motion::ok) return s;
    face(c, h, facing);
    if (drive_.moved()) {  // else: facing it already, scanned this step
      if (const Motion s = await_revolution(); s != Motion::ok) return s;
      scan(c);
    }
    if (const Motion s = rescan_while_unknown(c, [&] { return unknown(c, h); }); s != Motion::ok) return s;
    const std::pair<Cell, Heading> side{c, h};
    if (unknown(c, h) && grid_.contains(mapping::neighbour(c, h)) && std::ranges::find(unresolved_, side) == unresolved_.end()) {
      unresolved_.push_back(side);
    }
  }
  return Motion::ok;
}

Motion Arrival::confirm(Cell c) {
  for (const Heading h : mapping::kHeadings) {
    const auto reads_wall = [&] { return senses_.reads_side(c, h) == SideState::wall; };
    for (int attempt = 0; attempt < 3 * options_.max_rescans && walls_(c, h) == SideState::open && reads_wall();
         ++attempt) {
      if (const Motion s = rest_and_scan(c); s != Motion::ok) return s;
    }
  }
  return Motion::ok;
}

Motion Arrival::probe_unknown_sides(Cell c, Heading &facing) {
  for (const Heading h : mapping::kHeadings) {
    if (!unknown(c, h)) continue;
    if (const Motion s = probe(c, h); s != Motion::ok) return s;
    face(c, h, facing);
  }
  return Motion::ok;
}

Motion Arrival::probe(Cell c, Heading h) {
  if (const Motion s = drive_.turn_to(h); s != Motion::ok) return s;
  const mapping::Point centre = grid_.centre_of(c);
  const double limit_m = options_.geometry.cell_size_m / 2.0 + options_.geometry.subcell_size_m() / 2.0;
  const std::string what = fmt::format("probing {} of cell ({},{})", mapping::to_char(h), c.x, c.y);
  if (const Motion s = drive_.creep(h, centre, limit_m, what, [&] { return senses_.gather_bumps(c); }); s != Motion::ok) {
    return s;
  }
  senses_.apply_bumps();
  if (const Motion s = drive_.come_to_rest(); s != Motion::ok) return s;
  const Motion back = drive_.drive_to(centre, h, -drive_.travelled_m(), fmt::format("the centre of cell ({},{})", c.x, c.y),
                                      [&] { senses_.gather_bumps(c); });
  senses_.apply_bumps();
  return back;
}

Motion Arrival::look_around(Cell c, Heading &facing) {
  for (const Heading h : {mapping::turned_right(facing), mapping::opposite(facing), mapping::turned_left(facing)}) {
    if (const Motion s = drive_.turn_to(h); s != Motion::ok) return s;
    face(c, h, facing);
    scan(c);
  }
  return Motion::ok;
}

std::string Arrival::unresolved_sides() const {
  std::string text;
  int count = 0;
  for (const auto &[c, h] : unresolved_) {
    if (!unknown(c, h) || visits_.visited(mapping::neighbour(c, h))) continue;
    if (++count <= 3) text += fmt::format("{}{} of ({},{})", count > 1 ? ", " : "", mapping::to_char(h), c.x, c.y);
  }
  if (count == 0) return {};
  return fmt::format("{} side{} of visited cells still unknown: {}{}", count, count == 1 ? "" : "s", text,
                     count > 3 ? ", ..." : "");
}

}  // namespace robot
