// The embedded simulator for Python controllers: the runner (maze_mapper.run) builds a
// Simulation and makes it current; the controller's Robot attaches to it and sees only the
// webots:: devices (the Webots method names), never the maze.

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <array>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <pybind11/stl.h>
#include <webots/Device.hpp>
#include <webots/DistanceSensor.hpp>
#include <webots/GPS.hpp>
#include <webots/InertialUnit.hpp>
#include <webots/Lidar.hpp>
#include <webots/Motor.hpp>
#include <webots/PositionSensor.hpp>
#include <webots/Robot.hpp>
#include <webots/TouchSensor.hpp>

#include "app/run/profile_json.hpp"
#include "app/run/run_frame.hpp"
#include "bindings.hpp"
#include "run_files.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "common/random.hpp"
#include "maze/world/geometry.hpp"
#include "maze/world/world.hpp"
#include "maze/sim/simulation.hpp"
#include "maze/sim/simulation_sight.hpp"
#include "maze/world/world.hpp"
#include "maze/formats/xml_solids.hpp"

namespace maze_mapper_python {

namespace {

// The pose, as the file states it (m, rad), of the start position a maze read from the
// course's XML starts at: the <pos> its start cell and heading came from, a lattice node of
// 0.5 m cells included (the maze itself keeps cells). nullopt for another format.
std::optional<maze::sim::Pose> xml_start_pose(const maze::World &world) {
  if (world.format != maze::Format::xml) return std::nullopt;
  const maze::XmlArenaRead read = maze::read_xml_arena(maze::read_file(world.file), world.file);
  const std::vector<maze::StartPosition> positions = world.maze().start_positions();
  const maze::StartPosition start{world.maze().start(), world.maze().start_heading()};
  for (std::size_t i = 0; i < positions.size() && i < read.arena.starts.size(); ++i) {
    if (positions[i] == start) {
      const maze::ArenaPose &p = read.arena.starts[i];
      return maze::sim::Pose{p.x_m, p.y_m, p.yaw_rad};
    }
  }
  return std::nullopt;
}

// A simulation of one world and one robot, owned by the runner: a maze, or an arena (a
// course arena read from a file, or the course's empty floor that a supervisor fills).
class PySimulation {
 public:
  // max_steps: basic time steps before Robot::step returns -1 (0: no limit).
  // The robot starts where Webots puts it: on a course XML world, exactly on the file's pose.
  PySimulation(const maze::World &world, const std::string &robot, std::uint64_t seed, std::optional<double> noise,
               std::int64_t max_steps)
      : profile_(app::resolve_robot(robot)) {
    maze::sim::SimulationOptions o = options(seed, noise, max_steps);
    if (world.on_lattice()) o.start = xml_start_pose(world);
    frame_ = std::make_unique<app::RunFrame>(world, profile_, o, nullptr, -1);
  }

  webots::embedded::Simulation &simulation() { return frame_->simulation(); }
  const webots::embedded::Simulation &simulation() const { return frame_->simulation(); }

  void make_current() {
    if (!current_) current_ = std::make_unique<webots::embedded::CurrentSimulation>(simulation());
  }
  void release_current() { current_.reset(); }
  bool is_current() const { return webots::embedded::current_simulation() == &simulation(); }

  // The run's simulated time and basic steps, resets included (Robot.getTime() restarts at a reset).
  double time_s() const {
    return static_cast<double>(simulation().steps() * simulation().basic_time_step_ms()) / 1000.0;
  }
  std::int64_t steps() const { return simulation().steps(); }
  const maze::sim::RobotProfile &profile() const { return profile_; }
  void request_stop() { simulation().request_stop(); }
  // Whether this is the process that built the simulation (not a child the controller forked,
  // whose steps never reach the run or its files).
  bool in_owner_process() const { return ::getpid() == owner_pid_; }
  // A supervisor set the robot down: the recorded path has no line to its next pose (never
  // told the files from a forked child).
  void placed_by_supervisor() {
    if (files_ != nullptr && in_owner_process()) files_->mark_placed();
  }

  // From now on `files` observes the run: every control step's trace.csv row and replay
  // frame (record_trace).
  void record_to(py::object files) {
    files_ = &files.cast<RunFiles &>();
    files_->set_body_radius(profile_.body_radius_m);
    files_owner_ = std::move(files);
    frame_->add(files_);
  }
  // After a control step: told to the run's observers; whether the robot is at the goal.
  void after_step() {
    frame_->step(app::step_at(steps(), time_s(), simulation().pose()));
    if (!goal_reached_ && goal_.has_value()) goal_reached_ = at_goal(simulation().pose());
    if (!left_floor_ && webots::embedded::off_floor(simulation())) left_floor_ = report_left_floor();
  }

  // The run's goal: the cells of a lattice (cell_size_m, origin) the robot's centre reaches
  // one of, or points it comes within radius_m of. Replaces the goal set before.
  void set_goal(std::vector<std::pair<int, int>> cells, double cell_size_m, std::pair<double, double> origin,
                std::vector<std::pair<double, double>> points, double radius_m) {
    goal_ = Goal{std::move(cells), cell_size_m, origin, std::move(points), radius_m};
    goal_reached_ = goal_reached_ || at_goal(simulation().pose());
  }
  bool goal_reached() const { return goal_reached_; }
  // The goal points set_goal gave (none for goal cells or no goal).
  std::vector<std::pair<double, double>> goal_points() const {
    return goal_ ? goal_->points : std::vector<std::pair<double, double>>{};
  }

  // The device names of the robot, in the order Webots' Robot lists a robot's devices here:
  // motors, encoders, IMU, GPS, lidars, distance sensors, bumpers.
  std::vector<std::string> device_names() const {
    std::vector<std::string> names = {profile_.left_motor, profile_.right_motor, profile_.left_encoder,
                                      profile_.right_encoder};
    if (!profile_.imu.empty()) names.push_back(profile_.imu);
    if (!profile_.gps.empty()) names.push_back(profile_.gps);
    for (const auto &l : profile_.lidars) names.push_back(l.name);
    for (const auto &d : profile_.distance_sensors) names.push_back(d.name);
    for (const auto &b : profile_.bumpers) names.push_back(b.name);
    return names;
  }

 private:
  static maze::sim::SimulationOptions options(std::uint64_t seed, std::optional<double> noise, std::int64_t max_steps) {
    if (max_steps < 0) throw common::InputError("--max-steps must be at least 1 (got " + std::to_string(max_steps) + ")");
    maze::sim::SimulationOptions o;
    o.seed = seed;
    o.noise = noise;
    o.time_limit_s = static_cast<double>(max_steps) * o.basic_time_step_ms / 1000.0;
    o.validate();
    return o;
  }

  maze::sim::RobotProfile profile_;
  pid_t owner_pid_ = ::getpid();
  std::unique_ptr<app::RunFrame> frame_;  // the simulation, and the files observing it
  std::unique_ptr<webots::embedded::CurrentSimulation> current_;
  RunFiles *files_ = nullptr;  // files_owner_'s
  py::object files_owner_;

  struct Goal {
    std::vector<std::pair<int, int>> cells;
    double cell_size_m = 1.0;
    std::pair<double, double> origin;
    std::vector<std::pair<double, double>> points;
    double radius_m = 0.0;
  };
  bool at_goal(const maze::sim::Pose &p) const {
    const std::pair<int, int> cell{static_cast<int>(std::floor((p.x_m - goal_->origin.first) / goal_->cell_size_m)),
                                   static_cast<int>(std::floor((p.y_m - goal_->origin.second) / goal_->cell_size_m))};
    if (std::find(goal_->cells.begin(), goal_->cells.end(), cell) != goal_->cells.end()) return true;
    return std::any_of(goal_->points.begin(), goal_->points.end(), [&](const std::pair<double, double> &g) {
      return std::hypot(p.x_m - g.first, p.y_m - g.second) <= goal_->radius_m;
    });
  }
  std::optional<Goal> goal_;
  bool goal_reached_ = false;
  bool left_floor_ = false;  // reported once
  bool report_left_floor() const {
    const maze::sim::Pose &p = simulation().pose();
    py::module_::import("sys").attr("stderr").attr("write")(py::str(
        "warning: the robot left the floor at ({:.2f}, {:.2f}) m, t = {:.3f} s: past the Floor's edge\n").format(p.x_m, p.y_m, time_s()));
    return true;
  }
};

// The Python simulation object made current last (kept alive by the robots attached to it).
py::object &current_simulation_object() {
  static py::object *object = new py::object();  // never destroyed: outlives the interpreter's teardown
  return *object;
}

// The controller's handle: a webots::Robot on the current simulation.
class PyRobot {
 public:
  PyRobot() : simulation_(current_simulation_object()) {
    if (webots::embedded::current_simulation() == nullptr || simulation_.is_none()) {
      throw common::RuntimeFailure(
          "no simulation is running: run the controller with python3 -m maze_mapper.run CONTROLLER.py --world WORLD");
    }
    robot_ = std::make_unique<webots::Robot>();
    owner_ = &simulation_.cast<PySimulation &>();
    names_ = owner_->device_names();
  }
  // Webots' Robot.step: a negative duration is a mistake (raised); 0 passes no time. A stop
  // signal recorded (the runner's SIGINT, SIGTERM, SIGHUP) ends the simulation: -1. In a child
  // the controller forked, -1 at once: only the runner's process steps the run.
  int step(int duration_ms) {
    if (duration_ms < 0) {
      throw common::InputError("Robot.step: the duration must be 0 or more ms (got " + std::to_string(duration_ms) + ")");
    }
    if (!owner_->in_owner_process()) return -1;
    if (common::interrupted()) owner_->request_stop();
    const int result = robot_->step(duration_ms);
    owner_->after_step();
    return result;
  }
  double time_s() const { return robot_->getTime(); }
  double basic_time_step_ms() const { return robot_->getBasicTimeStep(); }
  std::string name() const { return robot_->getName(); }
  webots::Device *device(const std::string &name) { return robot_->getDevice(name); }
  const std::vector<std::string> &device_names() const { return names_; }

 private:
  py::object simulation_;
  PySimulation *owner_ = nullptr;  // simulation_'s
  std::unique_ptr<webots::Robot> robot_;
  std::vector<std::string> names_;
};

// A disabled device's three values are NaN in the simulator; Webots' Python API returns a list.
std::vector<double> three(const double *values) { return {values[0], values[1], values[2]}; }

std::optional<py::array_t<float>> range_image(const webots::Lidar &lidar) {
  const float *ranges = lidar.getRangeImage();
  if (ranges == nullptr) return std::nullopt;
  // One copy of the whole image (Webots' Python API also hands a snapshot, a list): it stays
  // as read when the robot steps on.
  const auto n = static_cast<py::ssize_t>(lidar.getHorizontalResolution());
  py::array_t<float> image(n);
  std::copy(ranges, ranges + n, image.mutable_data());
  return image;
}

template <typename Sensor>
void def_sampling(py::class_<Sensor, webots::Device> &c) {
  c.def("enable", &Sensor::enable, py::arg("sampling_period"))
      .def("disable", &Sensor::disable)
      .def("getSamplingPeriod", &Sensor::getSamplingPeriod)
      .def_property("sampling_period", &Sensor::getSamplingPeriod, &Sensor::enable);
}

void bind_devices(py::module_ &m) {
  py::class_<webots::Device>(m, "Device")
      .def("getName", &webots::Device::getName)
      .def("getModel", &webots::Device::getModel)
      .def_property_readonly("name", &webots::Device::getName)
      .def_property_readonly("model", &webots::Device::getModel);

  py::class_<webots::Lidar, webots::Device> lidar(m, "Lidar");
  def_sampling(lidar);
  // maze_mapper.controller wraps the array as Webots' list (RangeImage).
  lidar.def("_range_image", &range_image)
      .def("getHorizontalResolution", &webots::Lidar::getHorizontalResolution)
      .def("getNumberOfLayers", &webots::Lidar::getNumberOfLayers)
      .def("getFov", &webots::Lidar::getFov)
      .def("getMinRange", &webots::Lidar::getMinRange)
      .def("getMaxRange", &webots::Lidar::getMaxRange)
      .def("getFrequency", &webots::Lidar::getFrequency)
      .def("getMinFrequency", &webots::Lidar::getMinFrequency)
      .def("getMaxFrequency", &webots::Lidar::getMaxFrequency)
      .def("_set_rotating_frequency", &webots::Lidar::setFrequency, py::arg("frequency"))
      .def_property_readonly("horizontal_resolution", &webots::Lidar::getHorizontalResolution)
      .def_property_readonly("number_of_layers", &webots::Lidar::getNumberOfLayers)
      .def_property_readonly("fov", &webots::Lidar::getFov)
      .def_property_readonly("min_range", &webots::Lidar::getMinRange)
      .def_property_readonly("max_range", &webots::Lidar::getMaxRange)
      .def_property_readonly("frequency", &webots::Lidar::getFrequency);

  py::class_<webots::Motor, webots::Device>(m, "Motor")
      .def("setPosition", &webots::Motor::setPosition, py::arg("position"))
      .def("setVelocity", &webots::Motor::setVelocity, py::arg("velocity"))
      .def("getVelocity", &webots::Motor::getVelocity)
      .def("getMaxVelocity", &webots::Motor::getMaxVelocity)
      .def_property_readonly("max_velocity", &webots::Motor::getMaxVelocity);

  py::class_<webots::PositionSensor, webots::Device> encoder(m, "PositionSensor");
  def_sampling(encoder);
  encoder.def("getValue", &webots::PositionSensor::getValue)
      .def_property_readonly("value", &webots::PositionSensor::getValue);

  py::class_<webots::InertialUnit, webots::Device> imu(m, "InertialUnit");
  def_sampling(imu);
  const auto rpy = [](const webots::InertialUnit &u) { return three(u.getRollPitchYaw()); };
  imu.def("getRollPitchYaw", rpy).def_property_readonly("roll_pitch_yaw", rpy);

  py::class_<webots::GPS, webots::Device> gps(m, "GPS");
  def_sampling(gps);
  const auto values = [](const webots::GPS &g) { return three(g.getValues()); };
  gps.def("getValues", values).def_property_readonly("value", values);

  py::class_<webots::TouchSensor, webots::Device> touch(m, "TouchSensor");
  def_sampling(touch);
  touch.def("getValue", &webots::TouchSensor::getValue).def_property_readonly("value", &webots::TouchSensor::getValue);

  py::class_<webots::DistanceSensor, webots::Device> distance(m, "DistanceSensor");
  def_sampling(distance);
  distance.def("getValue", &webots::DistanceSensor::getValue)
      .def("getMinValue", &webots::DistanceSensor::getMinValue)
      .def("getMaxValue", &webots::DistanceSensor::getMaxValue)
      .def("getAperture", &webots::DistanceSensor::getAperture)
      .def("getType", [](const webots::DistanceSensor &d) { return static_cast<int>(d.getType()); })
      .def_property_readonly("value", &webots::DistanceSensor::getValue)
      .def_property_readonly("min_value", &webots::DistanceSensor::getMinValue)
      .def_property_readonly("max_value", &webots::DistanceSensor::getMaxValue)
      .def_property_readonly("aperture", &webots::DistanceSensor::getAperture)
      .def_property_readonly("type", [](const webots::DistanceSensor &d) { return static_cast<int>(d.getType()); });
  distance.attr("GENERIC") = static_cast<int>(webots::DistanceSensor::GENERIC);
  distance.attr("INFRA_RED") = static_cast<int>(webots::DistanceSensor::INFRA_RED);
  distance.attr("SONAR") = static_cast<int>(webots::DistanceSensor::SONAR);
  distance.attr("LASER") = static_cast<int>(webots::DistanceSensor::LASER);
}

}  // namespace

void bind_simulator(py::module_ &m) {
  bind_devices(m);

  py::class_<PySimulation>(m, "Simulation",
                           "The embedded simulator: a world and one robot (a built-in profile or a FILE.json). "
                           "maze_mapper.run builds one; a controller only sees its Robot.")
      .def(py::init<const maze::World &, const std::string &, std::uint64_t, std::optional<double>, std::int64_t>(),
           py::arg("world"), py::kw_only(), py::arg("robot") = "hambot", py::arg("seed") = common::kDefaultSeed,
           py::arg("noise") = py::none(), py::arg("max_steps") = 0)
      .def_static(
          "empty_floor",
          [](const std::string &robot, std::uint64_t seed, std::optional<double> noise, std::int64_t max_steps) {
            return std::make_unique<PySimulation>(maze::world_of(maze::course_empty_floor()), robot, seed, noise, max_steps);
          },
          py::kw_only(), py::arg("robot") = "hambot", py::arg("seed") = common::kDefaultSeed,
          py::arg("noise") = py::none(), py::arg("max_steps") = 0,
          "The course's empty floor (17 x 17 m centred on the origin), the robot at the origin facing north: "
          "the world a supervisor fills.")
      .def_property_readonly("in_arena", [](const PySimulation &s) { return s.simulation().on_solid_geometry(); })
      .def(
          "add_box",
          [](PySimulation &s, double cx, double cy, double half_length, double half_width, double angle, double height) {
            maze::Obstacle box = maze::Obstacle::oriented(cx, cy, half_length, half_width, angle);
            box.height_m = height;
            s.simulation().add_obstacle(box);
          },
          py::arg("centre_x_m"), py::arg("centre_y_m"), py::arg("half_length_m"), py::arg("half_width_m"),
          py::arg("angle_rad"), py::kw_only(), py::arg("height_m") = maze::kTallerThanEverySensor_m, "A solid box (its long axis at angle_rad from east) added to the world (a maze's is simulated on its geometry from then on).")
      .def(
          "add_cylinder",
          [](PySimulation &s, double cx, double cy, double radius, std::optional<double> height,
             std::optional<std::array<double, 3>> colour) {
            maze::ArenaDisc disc{cx, cy, radius};
            if (colour) disc.landmark = maze::ArenaDisc::Look{height.value_or(0.0), (*colour)[0], (*colour)[1], (*colour)[2]};
            s.simulation().add_disc(disc);
          },
          py::arg("centre_x_m"), py::arg("centre_y_m"), py::arg("radius_m"), py::kw_only(),
          py::arg("height_m") = py::none(), py::arg("colour") = py::none(),
          "A solid upright cylinder added to the world (a maze's is simulated on its geometry from then on); with "
          "a colour (red, green, blue, 0 to 1) a landmark, drawn in it.")
      .def(
          "remove_box",
          [](PySimulation &s, double cx, double cy, double half_length, double half_width, double angle) {
            return s.simulation().remove_obstacle(maze::Obstacle::oriented(cx, cy, half_length, half_width, angle));
          },
          py::arg("centre_x_m"), py::arg("centre_y_m"), py::arg("half_length_m"), py::arg("half_width_m"),
          py::arg("angle_rad"),
          "Takes out what the box covers of the world's boxes and walls (Node.remove): the number cut or taken.")
      .def(
          "remove_cylinder", [](PySimulation &s, double cx, double cy) { return s.simulation().remove_disc(cx, cy); },
          py::arg("centre_x_m"), py::arg("centre_y_m"),
          "Takes out the world's cylinders centred on (x, y) (Node.remove): how many.")
      .def(
          "built_world",
          [](const PySimulation &s) -> std::optional<maze::World> {
            const maze::Arena *geometry = s.simulation().geometry();
            if (geometry == nullptr) return std::nullopt;
            maze::Arena arena = *geometry;
            // The goal points the runner found with the controller's world (the course's empty floor).
            if (arena.goals.empty()) {
              for (const auto &[x, y] : s.goal_points()) {
                arena.goals.push_back({x, y});
                arena.goal_where.emplace_back();
              }
            }
            return maze::World(arena, "", maze::Format::room);
          },
          "The world as it stands now: the one the simulation began with and the solids a supervisor added since "
          "(with the goal points set_goal gave where it names none), or None while a maze's walls are untouched "
          "(its World is the file's).")
      .def(
          "teleport",
          [](PySimulation &s, double x, double y, double z, double yaw) {
            s.simulation().teleport({x, y, yaw}, z);
            s.placed_by_supervisor();
          },
          py::arg("x_m"), py::arg("y_m"), py::arg("z_m"), py::arg("yaw_rad"))
      .def("reset_world",
           [](PySimulation &s) {
             s.simulation().reset_world();
             s.placed_by_supervisor();
           })
      .def_property_readonly("collisions", [](const PySimulation &s) { return s.simulation().collisions(); },
                             "Steps in which the body met a solid after a step in which it met none.")
      .def_property_readonly("pose",
                             [](const PySimulation &s) {
                               const maze::sim::Pose &p = s.simulation().pose();
                               return py::make_tuple(p.x_m, p.y_m, s.simulation().height_m(), p.yaw_rad);
                             },
                             "The robot's true (x, y, z, yaw): the supervisor's view.")
      .def(
          "cast", [](const PySimulation &s, double x, double y, double angle, double max_range) {
            return s.simulation().cast(x, y, angle, max_range);
          },
          py::arg("x_m"), py::arg("y_m"), py::arg("angle_rad"), py::arg("max_range_m"),
          "The distance to the first solid along the ray, inf beyond max_range_m.")
      .def(
          "hits_along", [](const PySimulation &s, double x, double y, double angle, double max_range) {
            py::list out;
            const maze::Arena *g = s.simulation().geometry();
            for (const auto &h : webots::embedded::hits_along(s.simulation(), x, y, angle, max_range)) {
              const auto &look = h.disc >= 0 ? g->discs[static_cast<std::size_t>(h.disc)].landmark : std::nullopt;
              out.append(py::make_tuple(h.distance_m, h.top_m, look ? py::make_tuple(look->red, look->green, look->blue)
                                                                      : py::object(py::none())));
            }
            return out;
          },
          py::arg("x_m"), py::arg("y_m"), py::arg("angle_rad"), py::arg("max_range_m"),
          "Every solid the ray enters, nearest first: (distance, top above the floor, a landmark's (r, g, b) or None).")
      .def(
          "sight_blocked", [](const PySimulation &s, std::array<double, 3> a, std::array<double, 3> b, double half_depth) {
            return webots::embedded::sight_blocked(s.simulation(), {a[0], a[1], a[2]}, {b[0], b[1], b[2]}, half_depth);
          },
          py::arg("camera"), py::arg("target"), py::arg("half_depth_m"),
          "Webots' Recognition occlusion: whether a solid other than the target's cylinder is entered farther than "
          "half_depth_m from the target along the 3-D segment.")
      .def(
          "make_current",
          [](py::object self) {
            self.cast<PySimulation &>().make_current();
            current_simulation_object() = self;
          },
          "Makes this the simulation a controller's Robot() attaches to.")
      .def(
          "release_current",
          [](PySimulation &s) {
            s.release_current();
            current_simulation_object() = py::none();
          })
      .def("request_stop", &PySimulation::request_stop, "The controller's next step returns -1.")
      .def("set_goal", &PySimulation::set_goal, py::kw_only(), py::arg("cells"), py::arg("cell_size_m"),
           py::arg("origin"), py::arg("points"), py::arg("radius_m"),
           "The run's goal, checked after every control step: goal cells of a lattice, or points within radius_m.")
      .def_property_readonly("goal_reached", &PySimulation::goal_reached,
                             "Whether the robot's centre has been at the goal after a control step.")
      .def("record_trace", &PySimulation::record_to, py::arg("files"),
           "From now on the RunFiles record every control step (trace.csv, an arena's replay).")
      .def_property_readonly("time_s", &PySimulation::time_s)
      .def_property_readonly("steps", &PySimulation::steps)
      .def_property_readonly("robot_name", [](const PySimulation &s) { return s.profile().name; })
      .def_property_readonly("body_radius_m", [](const PySimulation &s) { return s.profile().body_radius_m; },
                             "The robot's body radius, m.")
      .def("device_names", &PySimulation::device_names);

  py::class_<PyRobot>(m, "RobotHandle")
      .def(py::init<>())
      .def("step", &PyRobot::step, py::arg("duration_ms"))
      .def("getTime", &PyRobot::time_s)
      .def("getBasicTimeStep", &PyRobot::basic_time_step_ms)
      .def("getName", &PyRobot::name)
      .def("device", &PyRobot::device, py::arg("name"), py::return_value_policy::reference_internal)
      .def("device_names", &PyRobot::device_names);
}

}  // namespace maze_mapper_python
