#pragma once
// The metric controller, beside the cell controller (robot/cell/controller.hpp): a robot in a
// room or arena, driving in continuous space and mapping onto a metric map
// (sensing/metric/map.hpp). Its pose is its own devices'
// (GPS and IMU; without a GPS, the encoders integrated along the IMU's yaw), never the truth.
// Every control step it scans (MetricSenses) and records its pose; the strategies:
//
//   waypoints  for each point: turn to it, then drive straight; a bump or a return ahead
//              closer than stop_distance_m stops the leg, and the run ends `blocked` saying
//              which leg and why. The list is driven `laps` times (after its last point, on
//              to its first again); laps 0: round and round until the time limit.
//   wavefront  the lab's loop: a cell is free when p < free_below_p (0.6), obstacles grown
//              by `dilate` cells, 4 neighbours; plan from the robot's cell to the goal's
//              (plan/metric/wavefront.hpp), drive to the path's next cell (the closest point of
//              the path), scanning every step; when it is reached, plan again from there on
//              the grown map. The growth keeps the way clear: the robot's cell and the
//              goal's are blocked only when the map calls them obstacles. Ends at the goal
//              (`goal_reached`), or `unreachable` when the wave does not reach the robot.
//   frontier   plan through cells seen free (p < free_below_p, observed, where the body,
//              body_radius_m, centred on the cell touches no cell seen occupied, or that the
//              robot's centre has driven through) to the frontier's target
//              (explore/metric/frontier.hpp: a cell within view_m of a frontier cell that
//              sees it, the least path against the gain of its group; groups under
//              min_frontier_m, enclosed ones and those none of whose cells the body could
//              cover are no targets, explore/metric/frontier_groups.hpp; with the lidar a
//              frontier cell borders a cell no beam has ended in), drive the path, then turn
//              a full turn there scanning; the drive ends early once its frontier cell is no
//              longer one (seen on the way). A
//              frontier cell still unobserved after visits that aimed at it, or left without
//              a target in a round where none had one, is set aside by itself, and tried again
//              once the map has progressed. When no frontier cell has a target, a probe drives
//              through the cells the map closes (explore/metric/sweep.hpp). Ends `done` when
//              no frontier is left, `incomplete` (with how many cells, and why) when frontier
//              cells are left and no target, retry or probe remains: the map no longer changes.
//              With a set-up whose nothing-seen marks nothing (the sonar cone) it first
//              sweeps: legs onto unobserved ground and probes past cells the echoes closed,
//              the body's cover (free) and contacts (occupied) standing over the echoes'.
//   wander     drive straight until a bump or a return ahead, back off back_off_m, turn a
//              seeded random 90 ... 180 deg either way; until the time limit (`time_up`).
//
// A time limit (time_limit_s > 0) ends any strategy `time_up`.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "explore/metric/frontier.hpp"
#include "explore/metric/frontier_groups.hpp"
#include "explore/metric/sweep.hpp"
#include "explore/strategies.hpp"
#include "mapping/grid_types.hpp"
#include "robot/control_loop.hpp"
#include "robot/drive.hpp"
#include "robot/options.hpp"
#include "robot/metric/senses.hpp"
#include "sensing/metric/map.hpp"

namespace webots {
class Robot;
}

namespace robot {

struct MetricOptions {
  // One of the strategies with a variant in metres (explore/strategies.hpp's table).
  explore::StrategyKind strategy = explore::StrategyKind::frontier;
  std::vector<mapping::Point> waypoints;
  int laps = 1;                         // waypoints: times the list is driven; 0: until time_limit_s
  std::optional<mapping::Point> goal;   // wavefront
  int dilate = 1;                       // cells (wavefront)
  double free_below_p = 0.6;
  double time_limit_s = 0.0;            // 0: none (wander needs one)
  double stop_distance_m = 0.2;         // a return ahead closer than this (from the centre) stops a leg
  double back_off_m = 0.1;              // wander
  double view_m = 0.5;                  // frontier: a target within this of its frontier
  double min_frontier_m = 0.1;          // frontier: a group shorter than this is no target
  std::uint64_t seed = 1;               // wander's turns
  double body_radius_m = 0.09;          // the cells under the body count as seen free for planning
  mapping::Point start;                 // where the robot starts (the lab gives it): odometry's origin without a GPS
};

// Throws common::InputError: a strategy without a variant in metres, waypoints empty for waypoints, no goal for wavefront, no time
// limit for wander or for laps 0, laps below 0, dilate outside 0 ... 8, a number not finite or out of range.
void validate(const MetricOptions &options);

enum class MetricEnding { done, goal_reached, arrived, blocked, unreachable, incomplete, time_up, no_progress,
                        max_steps, simulation_ended, stopped };
std::string_view to_string(MetricEnding e);

// What a step hook sees: the controller after a control step.
class MetricController;
using MetricStepHook = std::function<void(const MetricController &)>;

class MetricController {
 public:
  // The robot, options and map must outlive the controller; options validated by the caller.
  MetricController(webots::Robot &robot, const ControllerOptions &options, const MetricOptions &metric,
                   sensing::MetricMap &map, MetricStepHook on_step = {}, StopPoll stop_requested = nullptr);

  // Runs the strategy to its end.
  MetricEnding run();
  const std::string &message() const { return message_; }

  const sensing::MetricMap &map() const { return map_; }
  mapping::Point position() const { return position_; }
  double yaw_rad() const { return drive_.yaw_rad(); }
  std::int64_t steps() const { return loop_.steps(); }
  double time_s() const;
  const std::vector<mapping::Point> &trajectory() const { return trajectory_; }
  // The last plan: its cells (flat indices, start first) and the wave it came from
  // (plan/metric/wavefront.hpp's numbers; empty before a wavefront plan).
  const std::vector<std::size_t> &path() const { return path_; }
  const std::vector<std::int32_t> &wave() const { return wave_; }
  const MetricSenses &senses() const { return senses_; }
  // frontier: the frontier cells of groups worth a look when it ended
  // (explore/metric/frontier_groups.hpp), and the groups set aside then and why.
  std::size_t frontier_left() const { return frontier_left_; }
  const explore::FrontierSetAside &frontier_set_aside() const { return frontier_aside_; }
  // Whether the ground the body covers is observed free (sensing::MetricMap::observe_by_body).
  bool body_observes() const { return body_observes_; }
  // frontier's sweep legs (onto unobserved ground), and how many of them were probes.
  std::size_t sweep_legs() const { return sweep_legs_; }
  std::size_t probe_legs() const { return probe_legs_; }

 private:
  Motion step(Action action);
  void update_pose();
  void mark_under_body();
  // The body covers this cell: under_body_, and observed free the first time when body_observes_.
  void cover(std::size_t flat);
  // p >= free_below_p; a cell the body touched is (mark_contact), and with frontier and
  // body_observes_ one it covered is not (the body's own observations stand over the echoes').
  bool seen_occupied(std::size_t flat) const;
  // A bump, or a return ahead closer than stop_distance_m (waypoints, wander).
  bool blocked_ahead() const;
  // A bump, or a return ahead about to touch the body (legs planned on the grown map).
  bool touching_ahead() const;
  enum class StopWhen { never, obstacle_ahead, touching };
  // Turn to p, then drive straight to it, ending early as `when` says (sets *stopped then) or
  // once `done` says the drive has served its end (nullptr: never).
  Motion go_to(mapping::Point p, StopWhen when, bool *stopped, const std::function<bool()> *done = nullptr);
  Motion look_around();
  std::vector<bool> obstacles(bool unknown_blocked) const;
  // The cells seen occupied grown for planning: wavefront by `dilate` cells (the lab's rule);
  // frontier by the body's radius in metres (common/cell_clearance.hpp), except the cells
  // the robot has driven through.
  std::vector<bool> grown_obstacles(const std::vector<bool> &occupied) const;
  sensing::MetricCell robot_cell() const;
  MetricEnding finish(Motion m);

  MetricEnding run_waypoints();
  MetricEnding run_wavefront();
  MetricEnding run_frontier();
  // frontier's steps (robot/metric/controller_frontier.cpp). The target for the frontier
  // cells not set aside, else for those set aside before the map last progressed; none.
  std::optional<explore::FrontierTarget> next_frontier_target(const std::vector<bool> &frontier, int view_cells,
                                                              const explore::FrontierVisits &visits,
                                                              const std::vector<std::int32_t> &steps,
                                                              const explore::MapProgress &progress,
                                                              const std::vector<std::int32_t> &gain) const;
  // The progress of the map now (explore::progress_of on the planning map).
  explore::MapProgress progress_now(const explore::MapProgress &before) const;
  // Drives to the target and looks around there; a touch or a wedge on the way backs off; the
  // aim seen on the way (no frontier cell any more) ends the visit there.
  Motion visit_frontier(const explore::FrontierTarget &t, const std::vector<bool> &blocked);
  // Why frontier ended `incomplete`: the cells out of reach and those set aside.
  std::string frontier_left_message(std::size_t unreachable, std::size_t aside) const;
  // Drives path_'s corners until its end, a touch (sets *stopped), the rest of it seen blocked
  // or `done` saying the drive has served its end (nullptr: never).
  Motion drive_path_corners(bool *stopped, const std::function<bool()> *done = nullptr);
  // Straight back by back_off_m.
  Motion back_off();
  // The planner's view of the body's own observations (explore/metric/sweep.hpp).
  explore::BodyView body_view() const;
  bool covered_or_seen_free(std::size_t flat) const;
  // The next sweep leg, else a probe (probe_only: the probe alone); counted in sweep_legs_
  // and probe_legs_.
  std::optional<explore::SweepLeg> next_sweep_leg(const std::vector<std::int32_t> &steps,
                                                  const std::vector<bool> &swept, bool probe_only);
  // Drives to leg.from through `blocked`, then to leg.end; a touch or a wedge stops the leg
  // and the robot backs off; the drive ends once the rest of the leg would observe nothing
  // (explore::body_path_adds_nothing).
  Motion sweep(const explore::SweepLeg &leg, const std::vector<bool> &blocked);
  // A sweep or wavefront leg stopped by a touch or a wedge: the cell just ahead of the body's
  // rim is observed occupied (MetricMap::observe_contact) and stays so for planning; false when
  // that cell was touched before (or is the robot's own).
  bool mark_contact();
  MetricEnding run_wander();

  webots::Robot &robot_;
  const ControllerOptions &options_;
  const MetricOptions &metric_;
  sensing::MetricMap &map_;
  MetricStepHook on_step_;
  ControlLoop loop_;  // every control step, within --max-steps, until a stop or --time-limit
  WebotsChassis chassis_;
  Drive drive_;
  MetricSenses senses_;
  mapping::Point position_;
  WheelAngles last_wheels_;
  std::vector<mapping::Point> trajectory_;
  std::vector<std::size_t> path_;
  std::vector<std::int32_t> wave_;
  std::vector<bool> under_body_;  // cells the body has stood on: free whatever the map says
  std::vector<bool> driven_;      // cells the centre drove through: never grown over (frontier)
  std::size_t frontier_left_ = 0;
  explore::FrontierSetAside frontier_aside_;
  std::vector<bool> contact_;     // cells a touch or a wedge of a sweep or wavefront leg marked
  bool body_observes_ = false;  // the ground the body covers is observed free (MetricMap::observe_by_body)
  std::size_t sweep_legs_ = 0, probe_legs_ = 0;  // frontier's sweep legs, and the probes among them
  std::string message_;
};

}  // namespace robot
