// Ray integration, side by side: the same rays into the project's grid (`ray` model) and,
// when the bench was configured with OctoMap (Debian's liboctomap-dev), into an OcTree by
// insertPointCloud on a z = 0 plane at the same resolution with its default sensor model.
//
// Workload: 1,000 scans of 360 beams, ranges uniform in [0.9, 1.1] m, from an
// origin that moves 0.01 m and turns 0.01 rad per scan; 0.02 m sub-cells (K = 5, 0.1 m
// cells). `--repeat` rounds (default 5), each 10 grid passes then one OctoMap pass; rates
// are the medians over the rounds, the ratio the median of the rounds' ratios. Also times the scan-to-grid update of one 360-beam scan in the default world
// set-up (K = 3, 1 m cells, lidar max 12 m, 4 x 4 maze, robot in a cell centre).
// Times are the thread's CPU time (CLOCK_THREAD_CPUTIME_ID).
//
// Prints one `key: value` line per number (bench/run_all.sh reads them).
//   ./build/bench/bin/bench_ray_integration [--repeat N] [--grid-only]

#include <algorithm>
#include <ctime>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <vector>

#include "common/random.hpp"
#include "sensing/setups.hpp"
#include "mapping/occupancy_grid.hpp"
#include "sensing/scan.hpp"
#include "mapping/sensor_model.hpp"

#ifdef MAZE_MAPPER_HAVE_OCTOMAP
#include <octomap/octomap.h>
#endif

namespace {

// Thread CPU time, not wall time: on a shared 2-core machine a time slice given to another
// process would otherwise count against whichever side was running.
struct Clock {
  using time_point = double;
  static time_point now() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
  }
};

constexpr int kScans = 1000;
constexpr int kBeams = 360;
constexpr double kSubcell_m = 0.02;

struct Workload {
  std::vector<mapping::Point> origins;
  std::vector<double> yaws;
  std::vector<float> ranges;  // kScans * kBeams
};

Workload make_workload() {
  Workload w;
  common::Rng rng(20261121);
  for (int s = 0; s < kScans; ++s) {
    w.origins.push_back({1.5 + 0.01 * s, 2.0 + 0.3 * std::sin(0.01 * s)});
    w.yaws.push_back(0.01 * s);
    for (int b = 0; b < kBeams; ++b) w.ranges.push_back(static_cast<float>(rng.uniform(0.9, 1.1)));
  }
  return w;
}

sensing::LidarScan scan_of(const Workload &w, int s) {
  sensing::LidarScan scan;
  scan.origin = w.origins[static_cast<std::size_t>(s)];
  scan.yaw_rad = w.yaws[static_cast<std::size_t>(s)];
  scan.fov_rad = 2.0 * std::numbers::pi;
  scan.min_range_m = 0.05;
  scan.max_range_m = 12.0;
  scan.ranges = std::span<const float>(w.ranges.data() + static_cast<std::size_t>(s) * kBeams, kBeams);
  return scan;
}

double seconds_since(Clock::time_point t0) { return Clock::now() - t0; }

struct Result {
  double seconds = 0.0;
  std::uint64_t updates = 0;  // sub-cell updates (one per sub-cell per scan)
};

Result run_project(const Workload &w) {
  mapping::GridGeometry g;
  g.width_cells = 140;  // 14 m x 4 m of 0.1 m cells, 5 x 5 sub-cells of 0.02 m
  g.height_cells = 40;
  g.subcells = 5;
  g.cell_size_m = kSubcell_m * g.subcells;
  const mapping::SensorModel model{mapping::SensorModelOptions{}};
  mapping::OccupancyGrid grid(g, static_cast<float>(model.prior_log_odds()));
  sensing::ModelOptions options;
  options.kind = sensing::ModelKind::ray;
  mapping::ScanUpdate update;
  Result r;
  const auto t0 = Clock::now();
  for (int s = 0; s < kScans; ++s) {
    r.updates += sensing::integrate_scan(options, grid, scan_of(w, s), mapping::Cell{0, 0}, model, update);
  }
  r.seconds = seconds_since(t0);
  return r;
}

#ifdef MAZE_MAPPER_HAVE_OCTOMAP
octomap::Pointcloud cloud_of(const Workload &w, int s, octomap::point3d &origin) {
  const sensing::LidarScan scan = scan_of(w, s);
  octomap::Pointcloud cloud;
  cloud.reserve(kBeams);
  for (int b = 0; b < kBeams; ++b) {
    const double a = scan.beam_world_angle_rad(b);
    const double range = scan.ranges[static_cast<std::size_t>(b)];
    cloud.push_back(static_cast<float>(scan.origin.x_m + range * std::cos(a)),
                    static_cast<float>(scan.origin.y_m + range * std::sin(a)), 0.0f);
  }
  origin = octomap::point3d(static_cast<float>(scan.origin.x_m),
                            static_cast<float>(scan.origin.y_m), 0.0f);
  return cloud;
}

// insertPointCloud with the default sensor model (hit 0.7, miss 0.4, clamping 0.12/0.97).
// The point clouds are built before the clock starts.
Result run_octomap(const Workload &w) {
  std::vector<octomap::Pointcloud> clouds;
  std::vector<octomap::point3d> origins(kScans);
  for (int s = 0; s < kScans; ++s) clouds.push_back(cloud_of(w, s, origins[static_cast<std::size_t>(s)]));
  octomap::OcTree tree(kSubcell_m);
  Result r;
  const auto t0 = Clock::now();
  for (int s = 0; s < kScans; ++s) {
    tree.insertPointCloud(clouds[static_cast<std::size_t>(s)], origins[static_cast<std::size_t>(s)]);
  }
  r.seconds = seconds_since(t0);
  return r;
}

// The node updates of the workload, from computeUpdate (the key sets insertPointCloud
// applies, occupied winning), untimed.
std::uint64_t octomap_updates(const Workload &w) {
  std::vector<octomap::Pointcloud> clouds;
  std::vector<octomap::point3d> origins(kScans);
  for (int s = 0; s < kScans; ++s) clouds.push_back(cloud_of(w, s, origins[static_cast<std::size_t>(s)]));
  Result r;
  octomap::OcTree counter(kSubcell_m);
  for (int s = 0; s < kScans; ++s) {
    octomap::KeySet free_cells, occupied_cells;
    counter.computeUpdate(clouds[static_cast<std::size_t>(s)], origins[static_cast<std::size_t>(s)],
                          free_cells, occupied_cells, -1.0);
    for (const auto &k : free_cells) r.updates += occupied_cells.count(k) == 0 ? 1u : 0u;
    r.updates += occupied_cells.size();
  }
  return r.updates;
}
#endif

// The default world set-up: K = 3, 1 m cells, 4 x 4 maze, 360 beams, max 12 m, the robot
// in the centre of cell (1, 1) of a closed 4 x 4 box (ranges to the outer walls).
double scan_update_ns(int repeat) {
  mapping::GridGeometry g;
  g.width_cells = 4;
  g.height_cells = 4;
  const mapping::SensorModel model{mapping::SensorModelOptions{}};
  mapping::OccupancyGrid grid(g, static_cast<float>(model.prior_log_odds()));
  sensing::ModelOptions options;
  options.kind = sensing::ModelKind::ray;
  std::vector<float> ranges;
  sensing::LidarScan scan;
  scan.origin = {1.5, 1.5};
  scan.yaw_rad = std::numbers::pi / 2;
  scan.fov_rad = 2.0 * std::numbers::pi;
  scan.min_range_m = 0.05;
  scan.max_range_m = 12.0;
  for (int b = 0; b < kBeams; ++b) {
    const double a = scan.yaw_rad + scan.fov_rad / 2.0 - b * scan.fov_rad / kBeams;
    const double c = std::cos(a), s = std::sin(a);
    const double inner = 0.025;  // walls 0.05 m thick on the box's inside
    const double tx = c > 0 ? (4.0 - inner - 1.5) / c : (c < 0 ? (inner - 1.5) / c : 1e9);
    const double ty = s > 0 ? (4.0 - inner - 1.5) / s : (s < 0 ? (inner - 1.5) / s : 1e9);
    ranges.push_back(static_cast<float>(std::min(tx, ty)));
  }
  scan.ranges = ranges;
  mapping::ScanUpdate update;
  const int scans = 20000;
  double best = 1e300;
  for (int pass = 0; pass < repeat; ++pass) {
    const auto t0 = Clock::now();
    for (int i = 0; i < scans; ++i) {
      sensing::integrate_scan(options, grid, scan, mapping::Cell{1, 1}, model, update);
    }
    best = std::min(best, seconds_since(t0) / scans * 1e9);
  }
  return best;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2.0;
}

// The grid's time for one pass of the workload (s): the mean of `passes` passes, so that a
// round's grid side spans a time comparable to OctoMap's one pass; `fastest_s` keeps the
// fastest single pass seen.
double grid_pass_seconds(const Workload &w, int passes, std::uint64_t &updates, double &fastest_s) {
  double total = 0.0;
  for (int p = 0; p < passes; ++p) {
    const Result r = run_project(w);
    total += r.seconds;
    fastest_s = std::min(fastest_s, r.seconds);
    updates = r.updates;
  }
  return total / passes;
}

}  // namespace

int main(int argc, char **argv) {
  int repeat = 5;
  bool grid_only = false;  // the grid workload alone (for profiling it)
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--grid-only") == 0) {
      grid_only = true;
    } else {
      std::fprintf(stderr, "usage: %s [--repeat N] [--grid-only]\n", argv[0]);
      return 2;
    }
  }
  const Workload w = make_workload();
  const double rays = static_cast<double>(kScans) * kBeams;
  // Rounds of a grid side then an OctoMap side, so that both see the same machine; on a
  // shared machine its speed drifts, and the median of the rounds' ratios holds where a
  // ratio of two separate bests does not.
  constexpr int kGridPasses = 10;
  std::uint64_t grid_updates = 0;
  double grid_fastest_s = 1e300;
  std::vector<double> grid_s, octo_s, ratios;
  for (int round = 0; round < repeat; ++round) {
    grid_s.push_back(grid_pass_seconds(w, kGridPasses, grid_updates, grid_fastest_s));
#ifdef MAZE_MAPPER_HAVE_OCTOMAP
    if (!grid_only) {
      octo_s.push_back(run_octomap(w).seconds);
      ratios.push_back(octo_s.back() / grid_s.back());
    }
#endif
  }
  const double grid_median_s = median(grid_s);
  std::printf("workload: %d scans x %d beams, 0.9-1.1 m, %.2f m sub-cells; median of %d rounds "
              "(a round: %d grid passes, then 1 OctoMap pass)\n",
              kScans, kBeams, kSubcell_m, repeat, kGridPasses);
  std::printf("grid_rays_per_s: %.3e\n", rays / grid_median_s);
  std::printf("grid_updates_per_s: %.3e\n", static_cast<double>(grid_updates) / grid_median_s);
  std::printf("grid_ns_per_ray: %.1f\n", grid_median_s / rays * 1e9);
  std::printf("grid_fastest_pass_rays_per_s: %.3e\n", rays / grid_fastest_s);
  if (grid_only) return 0;
#ifdef MAZE_MAPPER_HAVE_OCTOMAP
  const double octo_median_s = median(octo_s);
  std::printf("octomap_rays_per_s: %.3e\n", rays / octo_median_s);
  std::printf("octomap_updates_per_s: %.3e\n", static_cast<double>(octomap_updates(w)) / octo_median_s);
  const double octo_fastest_s = *std::min_element(octo_s.begin(), octo_s.end());
  std::printf("octomap_fastest_pass_rays_per_s: %.3e\n", rays / octo_fastest_s);
  std::printf("ratio_grid_over_octomap: %.1f (median of the rounds' ratios; rounds %.1f to %.1f)\n",
              median(ratios), *std::min_element(ratios.begin(), ratios.end()),
              *std::max_element(ratios.begin(), ratios.end()));
  std::printf("ratio_fastest_passes: %.1f\n", octo_fastest_s / grid_fastest_s);
#else
  std::printf("octomap: not built (install liboctomap-dev, scripts/install-bench-deps.sh)\n");
#endif
  std::printf("scan_update_default_world_us: %.2f\n", scan_update_ns(repeat) / 1000.0);
  return 0;
}
