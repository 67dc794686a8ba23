#pragma once
// Where a rotating lidar's head last passed each beam (Webots' rotating Lidar; docs/simulator.md):
// the head turns `revolutions_per_step` revolutions (frequency x basic time step) a control
// step, clockwise from ahead; the s-th step after enabling (s from 1) sweeps the revolutions
// ((s - 1) r, s r]. Beam i lies at phase u_i in [0, 1) (LidarModel::sweep_phase), so the head
// passes it at revolutions u_i + k, k = 0, 1, ...

#include <cstdint>
#include <span>
#include <vector>

#include "maze/sim/sensors.hpp"

namespace maze::sim {

class LidarSweep {
 public:
  // revolutions_per_step > 0. start_revolutions: where the head stands when the sweep
  // begins, in revolutions clockwise from ahead (0 when enabled; where it had turned to when
  // its frequency changes); a beam then lies at phase u_i - start_revolutions (mod 1).
  LidarSweep(const LidarModel &model, double revolutions_per_step, double start_revolutions = 0.0);

  // The step (1 .. steps_enabled) of beam i's last pass at or before steps_enabled steps,
  // 0 when the head has not reached it yet. The reference: one beam, a division and two
  // roundings.
  std::int64_t last_pass_step(std::int64_t steps_enabled, int i) const;

  // out[i] = last_pass_step(steps_enabled, i) for every beam (out.size() beams). Along the
  // beams in phase order the value is non-decreasing within each of at most two runs (the
  // beams passed in this revolution, then those passed in the last one), every operation of
  // the reference being monotone in u; so each run is cut into its constant pieces by binary
  // search, a few reference evaluations a piece instead of one a beam. Bit for bit the same
  // (tested against the reference).
  void last_pass_steps(std::int64_t steps_enabled, std::span<std::int64_t> out) const;

 private:
  // Which pass: -1 before the first, else floor(turned - u) (the run a beam belongs to).
  std::int64_t pass_index(double turned, int i) const;

  std::vector<double> phase_;  // by beam index
  std::vector<int> by_phase_;  // beam indices, phase ascending
  double revolutions_per_step_;
};

}  // namespace maze::sim
