#pragma once
// Random arenas for tests and benchmarks: a walled rectangle with random solid rectangles,
// the same arena for the same options on every machine (common::Rng).

#include <cstdint>

#include "maze/world/geometry.hpp"

namespace maze {

struct ArenaGeneration {
  std::uint64_t seed = 1;
  double width_m = 10.0;   // the boundary: [0, width] x [0, height]
  double height_m = 10.0;
  int obstacles = 10;      // how many rectangles (fewer when the start or goal leaves no room)
  double min_side_m = 0.3;  // each rectangle's sides, uniform in [min, max]
  double max_side_m = 1.5;
  bool rotated = false;    // rectangles at random angles; else axis-aligned
  // Kept clear: no rectangle comes within this of the start (0.5, 0.5) m, facing east, or of
  // the goal (width - 0.5, height - 0.5) m.
  double clearance_m = 0.3;
};

// The arena: rectangles with centres uniform over the boundary, each drawn again (up to 100
// times) while it comes within the clearance of the start or the goal. Validated. Throws
// common::InputError for a boundary smaller than 1 x 1 m, a negative count, or sides that are
// not finite with 0 < min <= max.
Arena generate_arena(const ArenaGeneration &options);

}  // namespace maze
