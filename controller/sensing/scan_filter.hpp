#pragma once
// The range-filtering stage: what a lidar scan goes through before any model marks it, so
// that faulty beams bring no information instead of wrong information (docs/robustness.md).
//
// Each reading comes out as it went in, or as NaN ("no information", which every model
// ignores):
//   invalid    NaN, negative or below min range                        -> NaN
//   lone       a return with a no return on both sides, unless the nearest return on
//              one side (within `neighbour_reach`) agrees with it and is not lone itself:
//              a real return whose neighbours were dropped has the wall beyond them;
//              spikes in a view past max range have only each other  -> NaN
//   spike      a return that agrees with neither neighbouring return    -> NaN
//              (nearest returns within `neighbour_reach` beams on each side): it is further
//              than the tolerance from both, not between them, and not where the two returns
//              on either side, continued at their ratio, put it. Beams 1 degree apart on
//              one wall differ by millimetres, or grow steadily along a wall seen at a
//              grazing angle; a spike jumps.
//   see-through  a cluster of at most `max_see_through` agreeing returns further than the
//              returns on both sides of it (two spikes that happen to agree)  -> NaN
//              A return the rule would reject that the nearest return past the rejected
//              ones agrees with stays (a real return between two spikes). Both rules run
//              again after each round of rejections, so that spikes side by side cannot
//              vouch for each other.
//   dropout    a no return among returns: a run of at most `max_dropout_run` beams
//              without a return, with returns on both sides             -> NaN
//              A wall is not seen through between two beams that hit it, so a short run is
//              taken for dropped beams, unless the scan taken just before it from the same
//              pose read no return on every beam of the run too and the run is at least
//              `min_repeated_view` beams wide: then it is a view past max range (a corridor
//              seen end-on, longer than the lidar's range) and stands. A dropped beam is a
//              new draw at every scan (the chance that a run of k dropped beams repeats is
//              the dropout rate to the k-th power); a view is the same at every scan. Runs
//              longer than `max_dropout_run` stand at once.
// A no return outside such a run stays a no return (nothing within max range).
//
//   beams            0.50  inf   0.50  7.30  0.51  0.51  inf   inf   inf   inf   inf ...
//   filtered         0.50  NaN   0.50  NaN   0.51  0.51  inf   inf   inf   inf   inf ...
//                          dropout     spike             view past max range (a long run)
//   the same pose again, the run at beams 1 ... 3 read inf in both scans: a repeated view
//   beams            0.50  inf   inf   inf   0.51  ...    filtered  0.50  inf   inf   inf   0.51

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "sensing/scan.hpp"

namespace sensing {

struct ScanFilterOptions {
  // Standard deviation (m) of the lidar's range noise (Webots: noise x max range); the
  // spike tolerance grows with it so that noise alone rejects nothing.
  double range_noise_m = 0.01;
  // Beams on each side searched for a neighbouring return.
  int neighbour_reach = 3;
  // Widest cluster of agreeing returns (beams) rejected when it lies further than the
  // returns on both sides of it: a view through a wall is spikes vouching for each other.
  int max_see_through = 2;
  // Longest run of beams without a return, between returns, read as dropped beams.
  int max_dropout_run = 6;
  // Narrowest run of no returns that a repeat from the same pose confirms as a view past
  // max range (beams): one or two dropped beams repeat too often at a 5 % dropout rate
  // (5 %^2 and 5 %^4 a run), three seldom (5 %^6).
  int min_repeated_view = 3;
  // Two scans are from the same pose when their origins are this close (m) and their
  // headings within a quarter of a beam step.
  double same_pose_m = 0.01;

  // A wall seen this far from square-on (rad) still makes neighbouring returns agree: the
  // range grows by r tan(angle) per radian of beam step there (80 degrees: 10 % of the range
  // a 1-degree step).
  double max_grazing_rad = 80.0 * std::numbers::pi / 180.0;

  // How far (m) a return may differ from its neighbours for noise: 5 cm plus 5 sigma.
  double spike_tolerance_m() const { return 0.05 + 5.0 * range_noise_m; }
  // The further difference allowed per metre of range between beams beam_step_rad apart.
  double grazing_step(double beam_step_rad) const { return std::tan(max_grazing_rad) * beam_step_rad; }
};

// Throws common::InputError when an option is out of range (noise >= 0 and finite,
// reach 1 ... 10, dropout run 0 ... 32, repeated view 1 ... 32, same pose >= 0).
void validate(const ScanFilterOptions &options);

// What the last filtering did, beam counts.
struct ScanFilterCounts {
  std::size_t invalid = 0;
  std::size_t spikes = 0;
  std::size_t dropouts = 0;
};

class ScanFilter {
 public:
  explicit ScanFilter(const ScanFilterOptions &options = {});

  // The scan with its invalid, spiked and dropped readings replaced by NaN (the table
  // above); same pose, field of view and limits. Its ranges live in this filter: valid
  // until the next call. One pass over the beams, then each round looks only at the returns
  // that do not agree with the beam before them; no allocation after the first scan.
  LidarScan apply(const LidarScan &scan);
  // The same, with `before` the raw scan (unfiltered) taken just before this one: when it
  // is from the same pose (see ScanFilterOptions), a short run of no returns it read too is
  // a view past max range, not a dropout (the table above). From another pose it is ignored.
  LidarScan apply(const LidarScan &scan, const LidarScan &before);

  const ScanFilterCounts &counts() const { return counts_; }

 private:
  // apply(), with the scan before from the same pose or null.
  LidarScan filter(const LidarScan &scan, const LidarScan *before);
  // The beams and constants the rules read, for one round (scan_filter.cpp).
  struct Beams;
  Beams beams() const;
  // One round of each rule; true when it rejected a return.
  bool reject_spikes();
  bool reject_see_through();
  bool reject_collected();  // rejects the beams in rejected_
  // Takes back the spikes of rejected_ that a return not itself rejected agrees with (the
  // nearest on either side within reach, past the others): a real return between spikes.
  void keep_vouched_candidates();
  // before: the scan before from the same pose, or null.
  void drop_dropouts(const LidarScan *before);
  // Whether `before` is a scan of the same beams from the same pose as `scan`.
  bool same_pose(const LidarScan &scan, const LidarScan &before) const;

  ScanFilterOptions options_;
  // Of the scan being filtered, set once per apply(): the rules ask for them per beam.
  bool wrap_ = false;        // a full circle: beam 0 follows the last
  int reach_ = 0;            // neighbour reach, at most (n - 1) / 2 beams
  double absolute_m_ = 0.0;  // spike tolerance, m
  double relative_ = 0.0;    // its growth per metre of range between neighbouring beams
  std::vector<float> ranges_;
  // Per beam: a trusted return that continues the one before it (agrees with it) or starts
  // a stretch, a rejected return, or neither (no return, invalid).
  std::vector<unsigned char> state_;
  std::vector<int> starts_;  // the trusted returns that start a stretch: all a round looks at
  std::vector<int> rejected_;
  std::vector<int> starts_scratch_;  // keep_vouched_candidates' list, kept for its capacity
  ScanFilterCounts counts_;
};

}  // namespace sensing
