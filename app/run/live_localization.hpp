#pragma once
// `run --localize`: the localization lab's Task 2 on a robot run. The robot explores as the
// run's strategy drives it; a grid Bayes filter (localization.hpp) follows it knowing the
// maze's walls but not the start. At the start and at each arrival in a cell it
//   - predicts the move the robot made: the side towards the cell it arrived in from the one
//     it left, as the robot's odometry and compass tell it (one prediction a cell crossed);
//   - corrects with the four sides as its lidar reads them: a side is read as a wall when the
//     beam pointing that way (by the robot's heading, the robot knowing north) ends within one
//     cell size, and the reading goes through the lab's sensor model (--sensor).
// The filter is never told the start, the true pose or the strategy's map.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <ostream>
#include <vector>

#include "app/run/localization.hpp"
#include "app/run/run_observer.hpp"

namespace webots {
class Lidar;
}  // namespace webots

namespace app {

// One update of the filter: after the start scan (move 0) or an arrival.
struct LocalizationUpdate {
  std::int64_t step = 0;               // the control step it was made at
  int move = 0;                        // cell-to-cell moves so far
  std::optional<std::size_t> side;     // the move's side (0 N, 1 E, 2 S, 3 W); none at move 0
  loc::Reading reading{};              // the four sides as the lidar read them
  // After the correction, cell 1 (north-west) first; kept on mazes of at most
  // kMaxKeptBeliefCells cells, else empty.
  std::vector<double> belief;
  std::size_t likeliest = 0;           // the most likely cell's index (the first of the largest)
  double share = 0.0;                  // its belief
  std::size_t robot_cell = 0;          // where the robot's odometry says it is (index); not the filter's
};

// The filter's run, for the summary and the replay.
struct LocalizationSummary {
  loc::WallSensor sensor;
  double p_move = loc::kLabMotion;
  double localized_share = loc::kLabLocalized;
  std::optional<std::size_t> localized_at;  // the first update whose likeliest cell held localized_share
  std::vector<LocalizationUpdate> updates;  // the start's first
  int width = 0;                            // the maze's cells a row
};

// The largest maze whose belief is printed at every cell and kept for the replay (as demo
// localize prints it); a larger one prints and keeps the most likely cell alone.
inline constexpr std::size_t kMaxKeptBeliefCells = 400;

// Reads walls with `lidar`: the four sides' beams, chosen by `yaw_rad` (the robot's heading);
// a side is a wall when its beam ends within `cell_size_m`. Throws common::InputError when the
// lidar does not look all round (a side it cannot see).
loc::Reading lidar_walls(const webots::Lidar &lidar, double yaw_rad, double cell_size_m);

// The observer that runs the filter; prints each update to `out` (none: silent): the reading,
// the belief map and its numbers (on mazes of at most kMaxKeptBeliefCells cells) and the most
// likely cell.
class LiveLocalization final : public RunObserver {
 public:
  LiveLocalization(const LocalizationOptions &options, std::ostream *out);
  // Throws common::InputError when the run is not on the cell lattice, the robot has no lidar, or
  // its lidar does not see all four sides (ahead, left, right and behind).
  void on_start(const RunStart &start) override;
  void on_step(const RunStep &step) override;
  void on_end(const RunEnd &) override {}
  const LocalizationSummary &summary() const { return summary_; }

 private:
  void update(const robot::MoveReport &arrival, std::int64_t step);
  void print(const LocalizationUpdate &u) const;

  std::ostream *out_;
  loc::WallMap map_;
  const webots::Lidar *lidar_ = nullptr;
  double cell_size_m_ = 0.0;
  std::vector<double> belief_;
  std::optional<mapping::Cell> last_cell_;
  LocalizationSummary summary_;
};

// The summary's line: "cell 7 holds 0.912 after 24 moves, first localized at move 3 (step 812);
// the robot is in cell 7", or "not localized: most likely cell ...".
std::string localization_verdict(const LocalizationSummary &summary);

}  // namespace app
