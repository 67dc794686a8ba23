#pragma once
// The body sweep over a metric map (sensing/metric/map.hpp): frontier's legs onto unobserved
// ground for a set-up whose nothing-seen marks nothing (the sonar cone), and the probes every
// set-up drives when no frontier cell has a target (explore/metric/frontier.hpp). A leg goes
// from a cell reached through seen-free cells (`from`) onto a cell `aim`, ending at `end`;
// the controller (robot/metric/controller.hpp) drives it and stops it on a touch or a wedge,
// or once the rest of it would observe nothing (body_path_adds_nothing).
//
//   sweep leg  to the nearest unobserved cell not yet swept beside one covered or seen free
//              (by steps from the robot): onto its centre and on straight over unobserved
//              cells the body clears (at most kSweepReach_m), or, when the body cannot stand
//              on it (grown), to the point nearest `from` whose body covers its centre.
//   probe      from the nearest cell at the edge of the ground reached, straight on over
//              cells the map closes (seen occupied, or grown) to the first unobserved cell
//              within kSweepReach_m, and on over unobserved ones: through arcs a slanted echo
//              laid across open floor.
//
// Cost: O(cells) a leg.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "mapping/grid_types.hpp"
#include "sensing/metric/map.hpp"

namespace explore {

// How far past the cell it aims at a sweep leg goes on across unobserved ground, at most.
inline constexpr double kSweepReach_m = 3.0;

// What the robot's planner holds of the map besides its values: the cells its body's own
// observations decide.
struct BodyView {
  const sensing::MetricMap &map;
  double body_radius_m = 0.0;
  std::function<bool(std::size_t)> seen_occupied;        // for planning
  std::function<bool(std::size_t)> covered_or_seen_free;  // the body stood there, or p < 0.5
};

struct SweepLeg {
  std::size_t from = 0, aim = 0;
  mapping::Point end;
};

// Whether a body centred at p stays within the grid; and overlaps no cell seen occupied.
bool body_clear_at_edge(const BodyView &view, mapping::Point p);
bool body_clear_at(const BodyView &view, mapping::Point p);

// Whether the body driven straight from `from` to `to` would observe nothing more: every cell
// its centre would cross covered or seen free, and every cell it would overlap observed. A
// cell seen occupied on its line keeps a leg going (the body may find an arc's cell open), as
// does an unobserved one it would overlap.
bool body_path_adds_nothing(const BodyView &view, mapping::Point from, mapping::Point to);

// The sweep leg (above), or none in the body's reach. grown: the planning map without the
// unobserved cells; steps: from the robot per cell (-1 not reached); swept: cells a leg aimed
// at and left unobserved.
std::optional<SweepLeg> sweep_leg(const BodyView &view, const std::vector<bool> &grown,
                                  const std::vector<std::int32_t> &steps, const std::vector<bool> &swept);
// The probe (above), or none.
std::optional<SweepLeg> probe_leg(const BodyView &view, const std::vector<std::int32_t> &steps,
                                  const std::vector<bool> &swept);

}  // namespace explore
