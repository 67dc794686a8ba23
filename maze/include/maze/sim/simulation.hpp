#pragma once
// The embedded simulator: a world, one robot built from a profile, and simulated time, behind
// the webots:: device API (ARCHITECTURE.md). The composition root builds one and hands the robot
// to the controller, exactly as Webots starts a controller process:
//
//   maze::sim::SimulationOptions options;          // 32 ms basic step, seed, noise, limit
//   options.time_limit_s = 600.0;
//   webots::embedded::Simulation simulation(world, maze::sim::find_profile("hambot"), options);
//   webots::embedded::CurrentSimulation current(simulation);  // for `webots::Robot robot;`
//   run_controller();   // controller code: webots::Robot robot; ... robot.step(32) ...
//
// A default-constructed webots::Robot attaches to the simulation made current by a live
// CurrentSimulation (per thread); simulation.robot() is the same robot without that step.
//
// Physics: differential drive integrated exactly (arcs) in sub-steps short enough that the
// body moves at most a tenth of its radius; a body that would overlap a wall is pushed out
// along the contact normal, so motion into a wall stops and motion along it slides. Wheels
// slip against a wall: the encoders count what the motors turned.
// Sensors are lazy: a device computes its reading when read, at most once per basic step;
// noise comes from a Rng seeded by (seed, device, step), so readings do not depend on the
// order or number of reads. Readings reflect the current state as soon as a device is
// enabled (Webots waits for the first sampling period; a controller that steps before it
// reads sees no difference). A disabled device reads NaN (Lidar: nullptr).
// A rotating lidar (LidarSpec::frequency_hz > 0) is the exception, as in Webots: its head
// starts ahead when enabled and turns clockwise at its frequency; each beam reads as cast
// from the pose at the end of the basic step during which the head swept it (the simulation
// keeps the poses of the last revolution's steps), with noise and faults drawn from
// (seed, device, that step, beam); a beam not swept since enable reads 0.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/random.hpp"
#include "maze/world/geometry.hpp"
#include "maze/world/maze.hpp"
#include "maze/world/world.hpp"
#include "maze/sim/solid_geometry.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/lidar_sweep.hpp"
#include "maze/sim/sight.hpp"
#include "maze/sim/sensors.hpp"
#include "maze/sim/wall_grid.hpp"

namespace webots {
class Device;
class Robot;
}  // namespace webots

namespace maze::sim {

struct SimulationOptions {
  int basic_time_step_ms = 32;
  std::uint64_t seed = common::kDefaultSeed;
  double time_limit_s = 0.0;  // 0: none; else Robot::step returns -1 once it is reached
  // Overrides the profile's lidar noise (fraction of max range). 0 also turns off the
  // distance sensors' lookup-table noise: `--noise 0` makes every sensor exact.
  std::optional<double> noise;
  double gps_noise_m = 0.0;        // Gaussian sigma per coordinate
  double imu_noise_rad = 0.0;      // Gaussian sigma on yaw
  double encoder_noise_rad = 0.0;  // Gaussian sigma on each wheel angle
  // Where the robot starts; default: the centre of the maze's start cell, facing its start
  // heading (an arena: its start pose).
  std::optional<Pose> start;

  // Faults (all off by default). Drawn from a Rng seeded by (seed, device, step) apart from
  // the noise's, so turning a fault on leaves the noise as it was.
  double dropout = 0.0;      // fraction of lidar beams that read +infinity
  double spikes = 0.0;       // fraction of lidar beams that read a uniform range in [min, max]
  std::string stuck_bumper;  // this bumper always reads pressed (empty: none)
  double wheel_slip = 0.0;   // fraction of the wheels' turning that does not move the body;
                             // the encoders count it all

  // Throws common::InputError naming the first bad option.
  void validate() const;
};

}  // namespace maze::sim

namespace webots::embedded {

// The simulation's own bookkeeping of its wheels and devices (Simulation's private state).
namespace simulation_detail {

enum class DeviceKind { lidar, motor, encoder, imu, gps, touch, distance };
struct Wheel {
  double angle_rad = 0.0;
  double target_rad = 0.0;  // +infinity: velocity control
  double velocity_rad_s = 0.0;
};
// One entry per device, in creation order; `spec` indexes the profile's list of that kind
// (for motors and encoders: 0 left, 1 right).
struct DeviceState {
  DeviceKind kind;
  int spec = 0;
  int sampling_period_ms = 0;
  std::int64_t read_at_step = -1;  // the step whose reading `cache` holds
  std::int64_t enabled_at_step = -1;  // when the sampling period last went from 0 (lidars)
  std::vector<float> ranges;
  // A rotating lidar's image, beam by beam: the step whose pose beam i's range was cast
  // from (0: not swept yet, -1: never computed). A beam is cast again only when the head
  // has passed it since; its range is a function of that step alone (pose, noise stream).
  std::vector<std::int64_t> beam_steps;
  std::vector<std::int64_t> last_pass;  // scratch: LidarSweep::last_pass_steps
  double cache[3] = {0.0, 0.0, 0.0};
  // A rotating lidar's head: where it stood (revolutions from ahead) when its sweep began at
  // enabled_at_step, and whether that was a frequency change (then a beam the head has not
  // passed since keeps its reading).
  double sweep_start_rev = 0.0;
  bool sweep_resumed = false;
};

// The pose at the end of a step.
struct PastPose {
  std::int64_t step;
  maze::sim::Pose pose;
};

// Collisions counted as the steps in which the body met a solid after a step in which it met none.
struct Collisions {
  bool touching_this_step = false;  // the body was held out of a solid during this step
  bool touching_last_step = false;
  std::int64_t count = 0;
};

}  // namespace simulation_detail

class Simulation {
 public:
  // The robot in a world (a maze or an arena built in code: maze::world_of): a lattice
  // without landmarks on its wall grid (WallGrid), any other world, free geometry included,
  // on its geometry (SolidGeometry). The simulation keeps its own copy of the solids: the
  // world need not outlive it. Starts at options.start, else the world's; throws
  // common::InputError for bad options or start.
  using Profile = maze::sim::RobotProfile;
  using Options = maze::sim::SimulationOptions;
  Simulation(const maze::World &world, const Profile &profile, const Options &options);
  ~Simulation();
  Simulation(const Simulation &) = delete;
  Simulation &operator=(const Simulation &) = delete;

  Robot &robot() { return *robot_; }
  const maze::sim::RobotProfile &profile() const { return profile_; }
  // The solids: a lattice's wall grid (only while not on_solid_geometry()), else the geometry's.
  bool on_solid_geometry() const { return solids_.has_value(); }
  const maze::sim::WallGrid &walls() const { return *walls_; }
  const maze::sim::SolidGeometry &solid_geometry() const { return *solids_; }
  // The world's solids now, a supervisor's additions included, while on_solid_geometry()
  // (else null); the world's lattice, if it has one.
  const maze::Arena *geometry() const { return geometry_ ? &*geometry_ : nullptr; }
  const maze::Maze *lattice() const { return lattice_ ? &*lattice_ : nullptr; }

  // The truth, for the composition root, evaluation and tests (never the controller).
  const maze::sim::Pose &pose() const { return pose_; }
  // Simulated time (Robot::getTime), back to 0 at reset_world().
  std::int64_t time_ms() const { return time_ms_; }
  // Basic time steps since the simulation began, resets included: what the time limit bounds.
  std::int64_t steps() const { return steps_; }
  // Lidar beams cast so far, all lidars (bench/'s unit of work): fixed images read, rotating beams swept.
  std::int64_t lidar_beams_cast() const { return lidar_beams_cast_; }
  void request_stop() { stop_requested_ = true; }  // the next Robot::step returns -1 (Webots quits)
  // Collisions so far: the steps in which the body met a solid (was held out of it) after a
  // step in which it met none; pressing on against a wall is one collision.
  std::int64_t collisions() const { return collisions_.count; }

  // ---- a supervisor's edits (Webots' Supervisor API; the composition root's only) ----
  // Adds a solid, seen and met at once (a body it overlaps is pushed out as it moves); a lattice
  // is simulated on its geometry from then on. Throws common::InputError for a bad size.
  void add_obstacle(const maze::Obstacle &obstacle);
  void add_disc(const maze::ArenaDisc &disc);
  // Node.remove: takes what footprint covers of boxes along it, or cylinders at (x, y); how many.
  int remove_obstacle(const maze::Obstacle &footprint);
  int remove_disc(double x_m, double y_m);
  // Moves the robot to pose, its origin z_m above the floor (a supervisor's translation and
  // rotation): wheels as they were, every reading afresh, GPS z reading z_m from then on.
  void teleport(const maze::sim::Pose &pose, double z_m);
  double height_m() const { return height_m_; }
  // Webots' simulationReset ("Reset from Supervisor"): the solids added since the start gone,
  // the robot at its start pose, wheels at rest, encoders and simulated time at 0. The time
  // limit counts steps(), resets included, so a controller that resets still ends there.
  void reset_world();
  // The distance from (x, y) along angle_rad to the first solid, +infinity beyond max_range_m.
  double cast(double x_m, double y_m, double angle_rad, double max_range_m) const;

  // ---- plumbing for the webots:: device classes (maze/src/webots/) ----
  int step(int duration_ms);
  int basic_time_step_ms() const { return options_.basic_time_step_ms; }
  Device *device(const std::string &name);

  void set_sampling_period(int device, int period_ms);
  int sampling_period(int device) const;

  const float *lidar_range_image(int device);
  const maze::sim::LidarSpec &lidar_spec(int device) const;
  // A rotating lidar's head turns at frequency_hz on from where it stands (InputError: fixed).
  void set_lidar_frequency(int device, double frequency_hz);

  void motor_set_position(int device, double position_rad);
  void motor_set_velocity(int device, double velocity_rad_s);
  double motor_velocity(int device) const;
  double motor_max_velocity() const { return profile_.max_wheel_velocity_rad_s; }

  double encoder_value(int device);
  const double *imu_roll_pitch_yaw(int device);
  const double *gps_values(int device);
  double touch_value(int device);
  double distance_value(int device);
  const maze::sim::DistanceSensorSpec &distance_spec(int device) const;

 private:
  using Kind = simulation_detail::DeviceKind;
  using Wheel = simulation_detail::Wheel;
  using DeviceState = simulation_detail::DeviceState;
  using PastPose = simulation_detail::PastPose;

  template <typename D>
  void add_device(const std::string &name, Kind kind, int spec);
  void set_up();  // the constructor's part once the solids are set
  void use_geometry(maze::Arena geometry);  // the solids from now on: the geometry's, kept as geometry_
  void restart_sweep(DeviceState &state, double start_rev);  // from enabled_at_step, the head at start_rev
  void rebuild_solids();  // the solids built again from geometry_ after a supervisor's edit
  // f(the solids): the one choice between the wall grid and the geometry, made once per query.
  template <typename F>
  decltype(auto) with_solids(F &&f) const;
  template <typename Solids>
  void rotating_range_image_in(const Solids &solids, int device, DeviceState &state,
                               const maze::sim::LidarSpec &spec);
  void advance(double dt_s);  // one basic step of the drive: exact arcs at the wheels' constant rates
  void turn_wheel(Wheel &wheel, double rate_rad_s, double h_s, bool arrives);
  // The body along the arc of wheel rates (rad/s) for h_s: one arc in free space, arcs of at
  // most a tenth of the body radius each (pushed out of walls after each) near walls.
  void move_body(double left_rad_s, double right_rad_s, double h_s);
  static maze::sim::Pose arc_end(const maze::sim::Pose &from, double v_m_s, double w_rad_s, double h_s);
  // How many arcs to move the body in: 1 when the arc to `end` stays clear of every wall.
  int substeps_for(const maze::sim::Pose &end, double v_m_s, double w_rad_s, double h_s);
  // push_out, skipped while the body is inside the cached free_centres_ box (exact: the
  // box is conservative, so the pose is the same as with push_out every substep).
  void keep_body_out_of_walls();
  // A wheel's rate until its next change (position control: the set velocity towards the
  // target, 0 on it), and the time until it reaches its target at that rate (infinity:
  // never this way).
  double wheel_rate_rad_s(const Wheel &wheel) const;
  double time_to_target_s(const Wheel &wheel, double rate_rad_s) const;
  bool fresh(DeviceState &state);  // whether the cache holds this step's reading; marks it
  void read_disabled(DeviceState &state);  // a disabled three-value device reads NaN
  common::Rng rng_for(int device) const;
  double lidar_noise(const maze::sim::LidarSpec &spec) const;
  void apply_lidar_faults(int device, const maze::sim::LidarSpec &spec, std::vector<float> &ranges) const;
  void rotating_range_image(int device, DeviceState &state, const maze::sim::LidarSpec &spec);
  float faulty_beam(int device, const maze::sim::LidarSpec &spec, std::int64_t step, int beam,
                    float range) const;
  const maze::sim::Pose &pose_at_step(std::int64_t step) const;

  maze::sim::RobotProfile profile_;
  maze::sim::SimulationOptions options_;
  std::optional<maze::Maze> lattice_;                // the world's lattice, simulated on walls_
  std::optional<maze::sim::WallGrid> walls_;         // while solids_ is empty
  std::optional<maze::sim::SolidGeometry> solids_;    // the geometry's solids, when in use
  std::optional<maze::Arena> geometry_;              // the geometry solids_ is built from
  std::optional<maze::Arena> initial_geometry_;      // and as the world began (none: on walls_)
  maze::sim::LidarPlanes lidar_planes_;               // the solids above each lidar's plane
  maze::sim::Pose initial_pose_;
  double height_m_ = 0.0;                           // the robot's origin above the floor
  maze::sim::Pose pose_;
  // Where the body's centre touches no wall (WallGrid::free_centres), computed when the body last
  // left the previous box: inside it a substep needs no push_out (the pose changes in advance()).
  std::optional<maze::sim::Box> free_centres_;
  static constexpr int kLeftWheel = 0, kRightWheel = 1;  // wheels_[kLeftWheel]: left motor, encoder
  Wheel wheels_[2];
  std::int64_t time_ms_ = 0;
  std::int64_t steps_ = 0;
  double basic_step_s_ = 0.0;       // computed once from the options
  std::int64_t time_limit_ms_ = 0;  // 0: none
  std::int64_t lidar_beams_cast_ = 0;
  bool stop_requested_ = false;
  simulation_detail::Collisions collisions_;
  bool ended_ = false;
  std::vector<maze::sim::LidarModel> lidar_models_;  // one per profile lidar
  std::vector<std::optional<maze::sim::LidarSweep>> lidar_sweeps_;  // likewise; rotating ones only
  // The poses at the end of the last steps, oldest first: as many as a rotating lidar's image
  // can still hold; empty without one.
  std::vector<PastPose> history_;
  std::size_t history_steps_ = 0;
  std::vector<DeviceState> states_;
  std::vector<std::unique_ptr<Device>> devices_;
  std::unique_ptr<Robot> robot_;
};

template <typename F>
decltype(auto) Simulation::with_solids(F &&f) const {
  return !solids_ ? f(*walls_) : f(*solids_);
}

// Makes a simulation current for webots::Robot's default constructor while alive (per
// thread; nests, restoring the previous one when destroyed).
class CurrentSimulation {
 public:
  explicit CurrentSimulation(Simulation &simulation);
  ~CurrentSimulation();
  CurrentSimulation(const CurrentSimulation &) = delete;
  CurrentSimulation &operator=(const CurrentSimulation &) = delete;

 private:
  Simulation *previous_;
};

// The simulation a default-constructed Robot attaches to, or nullptr.
Simulation *current_simulation();

}  // namespace webots::embedded
