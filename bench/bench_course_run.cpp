// The course robot's unit costs: nanoseconds a control step and a lidar beam, from real runs.
//
// Each size N (default 64 and 256) is the maze `maze_mapper generate NxN --seed N` makes,
// run as `maze_mapper run FILE --quiet` runs it: the default robot (hambot, its fixed 360-beam
// lidar), model, strategy and seed, the simulator and the controller wired as app::run_maze
// wires them, and a step observer polled every step as the command line's Ctrl-C check is.
// What is timed is the controller's run alone (the maze, the final map and the summary are
// not), in thread CPU time (CLOCK_THREAD_CPUTIME_ID: a time slice given to another process
// on a shared machine does not count).
//
// The split: a first, untimed run records the pose and step of every lidar image the
// controller read (and a hash of each image); the lidar's share is then timed by computing
// those images again, alone, from the same poses with the same noise streams, as the
// simulator computes them (the replay's hash must match the run's, or the benchmark fails).
// Then, medians over the rounds:
//   ns a beam = lidar replay time / beams cast (Simulation::lidar_beams_cast)
//   ns a step = (run time - lidar replay time) / control steps
// so a step's cost holds everything but the lidar's images: the controller's drive loop, the
// physics, the device reads, the scan filter and the grid updates of its scans.
//
//   ./build/bench/bin/bench_course_run [--rounds N] [SIZE ...]

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <span>
#include <string>
#include <vector>

#include <webots/Lidar.hpp>
#include <webots/Robot.hpp>

#include "app/run/run.hpp"
#include "app/run/run_options.hpp"
#include "maze/generate/generator.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/sensors.hpp"
#include "maze/sim/simulation.hpp"
#include "robot/cell/controller.hpp"

namespace {

double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2.0;
}

// FNV-1a over the images' bytes: the replay must compute what the run read.
std::uint64_t hash_floats(std::uint64_t h, std::span<const float> values) {
  for (const float v : values) {
    unsigned char bytes[sizeof(float)];
    std::memcpy(bytes, &v, sizeof(float));
    for (const unsigned char b : bytes) h = (h ^ b) * 0x100000001b3ULL;
  }
  return h;
}

struct Image {
  std::int64_t step;
  maze::sim::Pose pose;
};

struct Recording {
  std::vector<Image> images;
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  std::int64_t steps = 0;
  std::int64_t beams = 0;
  int visited = 0;
};

struct Setup {
  maze::Maze truth;
  app::RunOptions options;
  maze::sim::RobotProfile profile;
  robot::ControllerOptions controller;
};

Setup make_setup(int side) {
  maze::GeneratorOptions g;
  g.width = side;
  g.height = side;
  g.seed = static_cast<std::uint64_t>(side);
  Setup s{maze::generate_maze(g), app::RunOptions{}, {}, {}};
  s.options.output.quiet = true;
  s.profile = maze::sim::find_profile(s.options.robot);
  s.controller = app::controller_options(s.options, s.truth, s.profile);
  return s;
}

volatile bool g_stop = false;  // stands for the command line's Ctrl-C flag
bool stop_requested() { return g_stop; }

// One run; with `record`, the images the controller read. Returns the run's CPU seconds.
double run_once(const Setup &s, Recording *record) {
  webots::embedded::Simulation sim(maze::world_of(s.truth), s.profile, s.options.simulation);
  robot::CellController controller(sim.robot(), s.controller);
  webots::Lidar *lidar = sim.robot().getLidar(s.profile.lidars.front().name);
  std::int64_t beams_seen = 0;
  const auto note_image = [&] {
    if (record == nullptr || sim.lidar_beams_cast() == beams_seen) return;
    beams_seen = sim.lidar_beams_cast();
    const auto n = static_cast<std::size_t>(lidar->getHorizontalResolution());
    record->images.push_back({sim.time_ms() / sim.basic_time_step_ms(), sim.pose()});
    record->hash = hash_floats(record->hash, std::span<const float>(lidar->getRangeImage(), n));
  };
  robot::RunHooks hooks;
  hooks.stop_requested = stop_requested;  // polled before each control step, as run_maze polls Ctrl-C
  if (record != nullptr) {
    hooks.on_step = [&](const robot::StepReport &) {
      note_image();
      return true;
    };
  }
  const double t0 = thread_cpu_s();
  const robot::RunResult result = controller.run(hooks);
  const double seconds = thread_cpu_s() - t0;
  note_image();
  if (record != nullptr) {
    record->steps = result.steps;
    record->beams = sim.lidar_beams_cast();
    record->visited = result.visited;
  }
  return seconds;
}

// The recorded images computed again, as Simulation::lidar_range_image computes a fixed
// lidar's (the profile's lidar is the simulation's device 0). Returns the CPU seconds.
double replay_lidar(const Setup &s, const Recording &r, std::uint64_t *hash) {
  const webots::embedded::Simulation sim(maze::world_of(s.truth), s.profile, s.options.simulation);
  const maze::sim::LidarSpec &spec = s.profile.lidars.front();
  const maze::sim::LidarModel model(spec);
  const double noise = s.options.simulation.noise.value_or(spec.noise);
  std::vector<float> out(static_cast<std::size_t>(spec.horizontal_resolution));
  std::uint64_t h = 0xcbf29ce484222325ULL;
  const double t0 = thread_cpu_s();
  for (const Image &image : r.images) {
    common::Rng rng = maze::sim::sensor_rng(s.options.simulation.seed, 0, image.step);
    model.range_image(sim.walls(), noise, image.pose, rng, out);
    if (hash != nullptr) h = hash_floats(h, out);
  }
  const double seconds = thread_cpu_s() - t0;
  if (hash != nullptr) *hash = h;
  return seconds;
}

int bench_size(int side, int rounds) {
  const Setup s = make_setup(side);
  if (s.profile.lidars.size() != 1 || s.profile.lidars.front().frequency_hz > 0.0 ||
      s.options.simulation.dropout > 0.0 || s.options.simulation.spikes > 0.0) {
    std::fprintf(stderr, "error: the default robot is no longer one fixed lidar without faults: adapt the replay\n");
    return 1;
  }
  Recording r;
  run_once(s, &r);
  std::uint64_t replay_hash = 0;
  replay_lidar(s, r, &replay_hash);
  if (replay_hash != r.hash || static_cast<std::int64_t>(r.images.size()) * 360 != r.beams) {
    std::fprintf(stderr, "error: %dx%d: the replayed images differ from the run's (%zu images, %lld beams)\n", side,
                 side, r.images.size(), static_cast<long long>(r.beams));
    return 1;
  }
  std::vector<double> run_s, lidar_s, step_ns, beam_ns;
  for (int i = 0; i < rounds; ++i) {
    run_s.push_back(run_once(s, nullptr));
    lidar_s.push_back(replay_lidar(s, r, nullptr));
    beam_ns.push_back(lidar_s.back() / static_cast<double>(r.beams) * 1e9);
    step_ns.push_back((run_s.back() - lidar_s.back()) / static_cast<double>(r.steps) * 1e9);
  }
  const double run = median(run_s), lidar = median(lidar_s);
  std::printf("%dx%d: %lld steps, %zu images, %lld beams, %d cells visited; median of %d rounds\n", side, side,
              static_cast<long long>(r.steps), r.images.size(), static_cast<long long>(r.beams), r.visited, rounds);
  std::printf("  run_cpu_s: %.3f (lidar %.3f, %.0f %%; rest %.3f)\n", run, lidar, 100.0 * lidar / run, run - lidar);
  std::printf("  ns_per_step: %.1f (rounds %.1f to %.1f)\n", median(step_ns),
              *std::min_element(step_ns.begin(), step_ns.end()), *std::max_element(step_ns.begin(), step_ns.end()));
  std::printf("  ns_per_beam: %.1f (rounds %.1f to %.1f)\n", median(beam_ns),
              *std::min_element(beam_ns.begin(), beam_ns.end()), *std::max_element(beam_ns.begin(), beam_ns.end()));
  std::printf("  us_per_visited_cell: %.1f\n", run / r.visited * 1e6);
  return 0;
}

}  // namespace

int main(int argc, char **argv) {
  int rounds = 5;
  std::vector<int> sizes;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--rounds") == 0 && i + 1 < argc) {
      rounds = std::max(1, std::atoi(argv[++i]));
    } else if (const int side = std::atoi(argv[i]); side >= 2 && side <= 4096) {
      sizes.push_back(side);
    } else {
      std::fprintf(stderr, "usage: %s [--rounds N] [SIZE ...]   (SIZE: cells a side, default 64 256)\n", argv[0]);
      return 2;
    }
  }
  if (sizes.empty()) sizes = {64, 256};
  for (const int side : sizes) {
    if (const int status = bench_size(side, rounds); status != 0) return status;
  }
  return 0;
}
