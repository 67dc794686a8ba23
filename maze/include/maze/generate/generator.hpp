#pragma once
// Random mazes: a perfect maze (every cell reachable, exactly one path between two cells),
// then a fraction of the remaining interior walls removed to make loops. The start is the
// south-west cell facing north; the goal is the centre cell, or the centre 2 x 2 (2 x 1,
// 1 x 2) cells when a side is even, as in micromouse. All randomness is common::Rng, so the
// same options give the same maze on every platform. Iterative: no recursion, any size.

#include <cstdint>
#include <string_view>

#include "common/random.hpp"
#include "maze/world/maze.hpp"

namespace maze {

enum class Algorithm {
  dfs,      // recursive backtracker (on an explicit stack): long corridors, few branches
  kruskal,  // random walls knocked down between separate regions: many short dead ends
  prim,     // grows from the start through a random frontier: short branches, radial feel
};

struct GeneratorOptions {
  int width = 16;
  int height = 16;
  std::uint64_t seed = common::kDefaultSeed;
  double loops = 0.0;  // fraction (0 ... 1) of the perfect maze's interior walls removed
  Algorithm algorithm = Algorithm::dfs;

  // Throws common::InputError naming the option when a value is out of range.
  void validate() const;
};

// "dfs", "kruskal", "prim"; throws common::InputError for anything else.
Algorithm parse_algorithm(std::string_view name);
// "16x16" -> {16, 16}; throws common::InputError unless both are 1 ... kMaxMazeSide.
Cell parse_size(std::string_view text);

// The number of interior walls the loops option removes from a perfect W x H maze:
// round(loops * (interior sides - (W*H - 1))).
std::size_t loop_walls_removed(const GeneratorOptions &options);

// Expects validated options.
Maze generate_maze(const GeneratorOptions &options);

}  // namespace maze
