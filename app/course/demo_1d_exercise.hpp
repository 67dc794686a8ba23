#pragma once
// `maze_mapper demo 1d`: the 1-D exercise (demo_1d.hpp) as the command runs it, from its options
// as typed to the text it prints: the set-up with every number the table can be checked
// against by hand, the table and the ASCII plot (demo_1d_render.hpp), and with a shuffled
// order whether the result is the given order's.

#include <cstdint>
#include <string>

#include "app/course/demo_1d.hpp"
#include "common/random.hpp"

namespace app::course {

// demo 1d's options as typed.
struct Demo1dInput {
  std::string measurements;         // comma-separated cm
  bool measurements_given = false;  // otherwise the exercise's list
  Demo1dOptions options;            // resolution, length, behind, the sensor model (measurements set below)
  std::string order = "given";      // given or shuffle
  std::uint64_t seed = common::kDefaultSeed;
  std::string svg_path;             // when set, the plot is also written there as SVG
};

struct Demo1dOutput {
  std::string text;  // what the command prints
  int status = 0;    // 1 when a shuffled order's result is not the given order's
};

// Checks the input (common::InputError naming the option: "--measurements item 3 is not a
// number (got 'abc')", "--order must be given or shuffle (got x)", and validate()'s), writes
// the SVG when asked, and returns the text.
Demo1dOutput run_demo_1d(const Demo1dInput &input);

}  // namespace app::course
