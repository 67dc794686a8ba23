#pragma once
// `maze_mapper demo trilaterate`: the localization lab's Task 1 (localization.hpp for the
// arithmetic, docs/lab-localization.md for the exercise), from its options as typed to the
// text it prints: the landmarks and distances, the closed form's A to F, x and y and the
// cell, and the probabilistic variant's 5 x 5 grid of cell scores.

#include <cstdint>
#include <optional>
#include <string>

namespace app::course {

// The distances the demo uses when neither --distances nor --pose is given (yellow, red,
// green; blue not measured).
inline constexpr const char *kDefaultDistances = "3.2,4.1,2.9";

struct DemoTrilaterateInput {
  // "Y,R,G" or "Y,R,G,B" in m, in the order yellow, red, green, blue; in a list of four one
  // item may be "-": that landmark not measured. Empty: --pose's, else kDefaultDistances.
  std::string distances;
  std::string pose;  // "X,Y" in m: the distances computed from it
  std::optional<double> noise_m;         // with pose: Gaussian noise of this sigma on each distance
  std::optional<std::uint64_t> seed;     // with noise (default 1)
  double sigma_m = 1.0;                  // the probabilistic variant's sigma
};

// Checks the input (common::InputError naming the option: "--distances needs 3 or 4 numbers
// (got 2)", "--noise applies with --pose (the distances are given)", ...) and returns the
// text.
std::string run_demo_trilaterate(const DemoTrilaterateInput &input);

}  // namespace app::course
