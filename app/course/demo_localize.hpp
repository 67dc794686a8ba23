#pragma once
// `maze_mapper demo localize [WORLD]`: the localization lab's Task 2, a grid Bayes filter (or
// a particle filter) over a known maze's cells (localization.hpp for the arithmetic,
// docs/lab-localization.md for the exercise), from its options as typed to the text it
// prints: the map with its cell numbers, then per step the reading, the move, the belief
// after prediction and after correction, and how the run ended.
//
// A step: the robot moves one cell (the filter predicts), reads its four sides (the filter
// corrects); step 0 is the first reading alone. The robot knows which way is north. Its true
// moves: --moves as given, else the right-hand rule (turn right if open, else ahead, else
// left, else back; facing north at the start). Without --seed its moves always succeed and
// its readings are exact; with --seed each move fails with 1 - --motion and each side is read
// through the sensor model.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/run/localization.hpp"

namespace app::course {

// The world demo localize maps when none is given (a shipped world).
inline constexpr const char *kLocalizeWorld = "loc5x5";

struct DemoLocalizeInput {
  std::string world;                  // empty: kLocalizeWorld
  std::optional<int> start;           // cell number (1 north-west, row by row); none: the world's start
  std::string moves;                  // "N,E,S,...": the robot's moves; empty: the right-hand rule
  int max_steps = 30;
  double motion = loc::kLabMotion;    // P(a move succeeds)
  std::string sensor;                 // "P1,P2,P3,P4"; empty: 0.8,0.2,0.4,0.6
  double localized = loc::kLabLocalized;  // the share of the belief (or particles) one cell must hold
  std::optional<std::uint64_t> seed;  // noisy moves and readings; the particles' draws
  std::optional<int> particles;       // a particle filter of this many particles
  bool explain = false;               // step 0's correction worked by hand, cell by cell
};

// How the run ended.
struct LocalizeResult {
  bool localized = false;
  int moves = 0;                 // moves made
  int true_cell = 0;             // where the robot is at the end
  int believed_cell = 0;         // the most likely cell (or the most particles')
  double believed_share = 0.0;   // its belief (or share of the particles)
  std::vector<int> alike_starts; // exact runs: the starts the same moves read the same walls from
};

struct DemoLocalizeOutput {
  std::string text;
  LocalizeResult result;
};

// Checks the input (common::InputError naming the option) and runs the filter.
DemoLocalizeOutput run_demo_localize(const DemoLocalizeInput &input);

}  // namespace app::course
