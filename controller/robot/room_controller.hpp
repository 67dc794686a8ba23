#pragma once
// The room controller, beside the cell controller: a robot in an arena, driving in continuous
// space and mapping onto the room map (sensing/room_map.hpp). Its pose is its own devices'
// (GPS and IMU; without a GPS, the encoders integrated along the IMU's yaw), never the truth.
// Every control step it scans (RoomSenses) and records its pose; the strategies:
//
//   waypoints  for each point: turn to it, then drive straight; a bump or a return ahead
//              closer than stop_distance_m stops the leg, and the run ends `blocked` saying
//              which leg and why. The list is driven `laps` times (after its last point, on
//              to its first again); laps 0: round and round until the time limit.
//   wavefront  the lab's loop: a cell is free when p < free_below_p (0.6), obstacles grown
//              by `dilate` cells, 4 neighbours; plan from the robot's cell to the goal's
//              (plan/room_wavefront.hpp), drive to the path's next cell (the closest point of
//              the path), scanning every step; when it is reached, plan again from there on
//              the grown map. The growth keeps the way clear: the robot's cell and the
//              goal's are blocked only when the map calls them obstacles. Ends at the goal
//              (`goal_reached`), or `unreachable` when the wave does not reach the robot.
//   frontier   plan through cells seen free (p < free_below_p, observed, where the body,
//              body_radius_m, centred on the cell touches no cell seen occupied, or that the
//              robot's centre has driven through) to the nearest cell within view_m of a frontier
//              (an unobserved cell beside one seen free), drive the path, then turn a full
//              turn there scanning. A frontier still unobserved after a visit that aimed at it
//              is set aside. Ends `done` when no frontier is left, `incomplete` (with how many
//              cells) when only set-aside or unreachable ones are. With a set-up whose
//              nothing-seen marks nothing (the sonar cone) it first sweeps: legs onto
//              unobserved ground and probes past cells the echoes closed (robot/room_sweep.cpp),
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

#include "mapping/grid_types.hpp"
#include "robot/drive.hpp"
#include "robot/options.hpp"
#include "robot/room_senses.hpp"
#include "sensing/room_map.hpp"

namespace webots {
class Robot;
}

namespace robot {

enum class RoomStrategy { waypoints, wavefront, frontier, wander };
std::string_view to_string(RoomStrategy s);
// "waypoints", "wavefront", "frontier" or "wander"; common::InputError naming --strategy.
RoomStrategy parse_room_strategy(std::string_view name);

struct RoomOptions {
  RoomStrategy strategy = RoomStrategy::frontier;
  std::vector<mapping::Point> waypoints;
  int laps = 1;                         // waypoints: times the list is driven; 0: until time_limit_s
  std::optional<mapping::Point> goal;   // wavefront
  int dilate = 1;                       // cells (wavefront)
  double free_below_p = 0.6;
  double time_limit_s = 0.0;            // 0: none (wander needs one)
  double stop_distance_m = 0.2;         // a return ahead closer than this (from the centre) stops a leg
  double back_off_m = 0.1;              // wander
  double view_m = 0.5;                  // frontier: a target within this of its frontier
  std::uint64_t seed = 1;               // wander's turns
  double body_radius_m = 0.09;          // the cells under the body count as seen free for planning
  mapping::Point start;                 // where the robot starts (the lab gives it): odometry's origin without a GPS
};

// Throws common::InputError: waypoints empty for waypoints, no goal for wavefront, no time
// limit for wander or for laps 0, laps below 0, dilate outside 0 ... 8, a number not finite or out of range.
void validate(const RoomOptions &options);

enum class RoomEnding { done, goal_reached, arrived, blocked, unreachable, incomplete, time_up, no_progress,
                        max_steps, simulation_ended, stopped };
std::string_view to_string(RoomEnding e);

// What a step hook sees: the controller after a control step.
class RoomController;
using RoomStepHook = std::function<void(const RoomController &)>;
// Asked before every control step; true ends the run `stopped` (Ctrl-C, SIGTERM).
using RoomStopPoll = bool (*)();

class RoomController {
 public:
  // The robot, options and map must outlive the controller; options validated by the caller.
  RoomController(webots::Robot &robot, const ControllerOptions &options, const RoomOptions &room,
                 sensing::RoomMap &map, RoomStepHook on_step = {}, RoomStopPoll stop_requested = nullptr);

  // Runs the strategy to its end.
  RoomEnding run();
  const std::string &message() const { return message_; }

  const sensing::RoomMap &map() const { return map_; }
  mapping::Point position() const { return position_; }
  double yaw_rad() const { return drive_.yaw_rad(); }
  std::int64_t steps() const { return steps_; }
  double time_s() const;
  const std::vector<mapping::Point> &trajectory() const { return trajectory_; }
  // The last plan: its cells (flat indices, start first) and the wave it came from
  // (plan/room_wavefront.hpp's numbers; empty before a wavefront plan).
  const std::vector<std::size_t> &path() const { return path_; }
  const std::vector<std::int32_t> &wave() const { return wave_; }
  const RoomSenses &senses() const { return senses_; }
  // frontier: cells still unobserved beside seen-free ones when it ended.
  std::size_t frontier_left() const { return frontier_left_; }
  // Whether the ground the body covers is observed free (sensing::RoomMap::observe_by_body).
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
  // Whether the line between two cells' centres crosses no cell seen occupied (besides `to`).
  bool sees(std::size_t from, std::size_t to) const;
  // Cells within view_cells steps (over cells not seen occupied) of a frontier cell: their
  // steps (-1 beyond) and the frontier cell they are nearest.
  void spread_view(const std::vector<bool> &frontier, int view_cells, std::vector<std::int32_t> &near,
                   std::vector<std::size_t> &nearest_frontier) const;
  // A bump, or a return ahead closer than stop_distance_m (waypoints, wander).
  bool blocked_ahead() const;
  // A bump, or a return ahead about to touch the body (legs planned on the grown map).
  bool touching_ahead() const;
  enum class StopWhen { never, obstacle_ahead, touching };
  // Turn to p, then drive straight to it, ending early as `when` says; sets *stopped then.
  Motion go_to(mapping::Point p, StopWhen when, bool *stopped);
  Motion look_around();
  std::vector<bool> obstacles(bool unknown_blocked) const;
  // The cells seen occupied grown for planning: wavefront by `dilate` cells (the lab's rule);
  // frontier by the body's radius in metres (common/cell_clearance.hpp), except the cells
  // the robot has driven through.
  std::vector<bool> grown_obstacles(const std::vector<bool> &occupied) const;
  sensing::RoomCell robot_cell() const;
  RoomEnding finish(Motion m);

  RoomEnding run_waypoints();
  RoomEnding run_wavefront();
  RoomEnding run_frontier();
  // frontier's steps (robot/room_frontier.cpp). The cell to drive to: the nearest by `steps`
  // (from the robot, -1 unreachable) within view of a frontier cell (closer after each visit
  // that left it unobserved, `attempts`) that sees it; map_.size() when none. Fills
  // nearest_frontier (spread_view's).
  std::size_t frontier_target(const std::vector<bool> &frontier, int view_cells,
                              const std::vector<std::uint8_t> &attempts, const std::vector<std::int32_t> &steps,
                              std::vector<std::size_t> &nearest_frontier) const;
  // Drives path_'s corners until its end, a touch (sets *stopped) or the rest of it seen blocked.
  Motion drive_path_corners(bool *stopped);
  // Straight back by back_off_m.
  Motion back_off();
  // The body sweep (robot/room_sweep.cpp; set-ups whose nothing-seen marks nothing): a leg
  // from a cell reached through seen-free cells (`from`) onto the frontier cell `aim`, ending
  // at `end`: aim's centre and on straight over unobserved cells the body clears (at most
  // kSweepReach_m), or, when the body cannot stand on aim, the point nearest `from` whose
  // body covers aim's centre.
  struct SweepLeg {
    std::size_t from = 0, aim = 0;
    mapping::Point end;
  };
  // The leg to the nearest unobserved cell not `swept` beside one covered or seen free (by
  // `steps` from the robot); none when no such cell is in the body's reach.
  std::optional<SweepLeg> sweep_leg(const std::vector<std::int32_t> &steps, const std::vector<bool> &swept) const;
  // When none is: a probe, from the nearest cell at the edge of the ground reached, straight
  // on over cells the map closes (seen occupied by echoes, or grown) to the first unobserved
  // cell within kSweepReach_m and on over unobserved ones; stopped only by a touch or a wedge.
  std::optional<SweepLeg> probe_leg(const std::vector<std::int32_t> &steps, const std::vector<bool> &swept) const;
  // The last cell from c on, a step d at a time, while `on` holds and the body clears the edge.
  sensing::RoomCell run_end(sensing::RoomCell c, std::pair<int, int> d, const std::function<bool(std::size_t)> &on) const;
  bool covered_or_seen_free(std::size_t flat) const;
  // Drives to leg.from through `blocked`, then to leg.end; a touch or a wedge stops the leg
  // and the robot backs off.
  Motion sweep(const SweepLeg &leg, const std::vector<bool> &blocked);
  // Whether a body centred at p overlaps no cell seen occupied and stays within the grid;
  // only the latter.
  bool body_clear_at(mapping::Point p) const;
  bool body_clear_at_edge(mapping::Point p) const;
  // A sweep or wavefront leg stopped by a touch or a wedge: the cell just ahead of the body's
  // rim is observed occupied (RoomMap::observe_contact) and stays so for planning; false when
  // that cell was touched before (or is the robot's own).
  bool mark_contact();
  RoomEnding run_wander();

  webots::Robot &robot_;
  const ControllerOptions &options_;
  const RoomOptions &room_;
  sensing::RoomMap &map_;
  RoomStepHook on_step_;
  RoomStopPoll stop_requested_;
  int time_step_ms_;
  WebotsChassis chassis_;
  Drive drive_;
  RoomSenses senses_;
  mapping::Point position_;
  WheelAngles last_wheels_;
  std::int64_t steps_ = 0;
  bool time_up_ = false;
  std::vector<mapping::Point> trajectory_;
  std::vector<std::size_t> path_;
  std::vector<std::int32_t> wave_;
  std::vector<bool> under_body_;  // cells the body has stood on: free whatever the map says
  std::vector<bool> driven_;      // cells the centre drove through: never grown over (frontier)
  std::size_t frontier_left_ = 0;
  std::vector<bool> contact_;     // cells a touch or a wedge of a sweep or wavefront leg marked
  bool body_observes_ = false;  // the ground the body covers is observed free (RoomMap::observe_by_body)
  std::size_t sweep_legs_ = 0, probe_legs_ = 0;  // frontier's sweep legs, and the probes among them
  std::string message_;
};

}  // namespace robot
