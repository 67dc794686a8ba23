#include "app/run/live_localization.hpp"

#include <webots/Lidar.hpp>
#include <webots/Robot.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include <fmt/format.h>

#include "app/run/localization_text.hpp"
#include "common/error.hpp"

namespace app {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The angle in [-pi, pi).
double wrapped_rad(double a) {
  a = std::fmod(a + std::numbers::pi, kTwoPi);
  return (a < 0.0 ? a + kTwoPi : a) - std::numbers::pi;
}

// The beam of `lidar` nearest `relative_rad` from its heading (lidar.hpp's beam order), or
// none when no beam looks within half a beam's width of it.
std::optional<int> beam_towards(const webots::Lidar &lidar, double relative_rad) {
  const int n = lidar.getHorizontalResolution();
  const double fov = lidar.getFov(), width = fov / n;
  const double pixel_centre = lidar.getFrequency() > 0.0 ? 0.0 : 0.5;
  const double rel = wrapped_rad(relative_rad);
  // Beam i looks at fov/2 - (i + pixel_centre) * width.
  const auto beam = static_cast<int>(std::lround((fov / 2 - rel) / width - pixel_centre));
  const int wrapped = fov >= kTwoPi - 1e-9 ? ((beam % n) + n) % n : beam;
  if (wrapped < 0 || wrapped >= n) return std::nullopt;
  const double off = wrapped_rad(fov / 2 - (wrapped + pixel_centre) * width - rel);
  if (std::abs(off) > width) return std::nullopt;
  return wrapped;
}

std::size_t likeliest_of(const std::vector<double> &belief) {
  return static_cast<std::size_t>(std::distance(belief.begin(), std::max_element(belief.begin(), belief.end())));
}

}  // namespace

// The beam towards compass side `side` when the robot faces `yaw_rad`; common::InputError when
// the lidar has none.
int beam_for_side(const webots::Lidar &lidar, std::size_t side, double yaw_rad) {
  const auto compass = static_cast<common::Compass>(side);
  const std::optional<int> beam = beam_towards(lidar, common::yaw_rad(compass) - yaw_rad);
  if (!beam) {
    throw common::InputError(fmt::format(
        "--localize reads the four sides with the lidar, and its field of view ({:.0f} degrees) leaves out the {}",
        lidar.getFov() * 180.0 / std::numbers::pi, common::to_char(compass)));
  }
  return *beam;
}

loc::Reading lidar_walls(const webots::Lidar &lidar, double yaw_rad, double cell_size_m) {
  const float *ranges = lidar.getRangeImage();
  if (ranges == nullptr) throw common::InputError("--localize reads the walls with the lidar, and the lidar is disabled");
  loc::Reading z{};
  for (std::size_t side = 0; side < 4; ++side) {
    const float range = ranges[beam_for_side(lidar, side, yaw_rad)];
    z[side] = std::isfinite(range) && range < cell_size_m;
  }
  return z;
}

LiveLocalization::LiveLocalization(const LocalizationOptions &options, std::ostream *out) : out_(out) {
  summary_.sensor = loc::parse_sensor(options.sensor);
  summary_.p_move = options.motion;
  summary_.localized_share = options.localized;
}

void LiveLocalization::on_start(const RunStart &start) {
  if (start.cell == nullptr) throw common::InputError("--localize follows a run on a maze's cells");
  const std::string &name = start.cell->controller.devices.lidar;
  lidar_ = name.empty() ? nullptr : start.robot.getLidar(name);
  if (lidar_ == nullptr) throw common::InputError("--localize reads the walls with a lidar, and the robot has none");
  for (std::size_t side = 0; side < 4; ++side) beam_for_side(*lidar_, side, 0.0);  // facing east: all four round it
  map_ = loc::wall_map(start.cell->truth);
  cell_size_m_ = start.cell->truth.cell_size_m();
  summary_.width = map_.width;
  belief_.assign(map_.cells(), 1.0 / static_cast<double>(map_.cells()));
}

void LiveLocalization::on_step(const RunStep &step) {
  if (step.arrival != nullptr) update(*step.arrival, step.step);
}

void LiveLocalization::update(const robot::MoveReport &arrival, std::int64_t step) {
  LocalizationUpdate u;
  u.step = step;
  u.move = arrival.moves;
  if (last_cell_ && *last_cell_ != arrival.cell) {
    const int dx = arrival.cell.x - last_cell_->x, dy = arrival.cell.y - last_cell_->y;
    const auto side = static_cast<std::size_t>(dy > 0 ? 0 : dx > 0 ? 1 : dy < 0 ? 2 : 3);
    u.side = side;
    for (int crossed = std::max(std::abs(dx), std::abs(dy)); crossed > 0; --crossed)
      belief_ = loc::predict(map_, belief_, side, summary_.p_move);
  }
  last_cell_ = arrival.cell;
  u.reading = lidar_walls(*lidar_, mapping::yaw_rad(arrival.heading), cell_size_m_);
  belief_ = loc::correct(map_, summary_.sensor, belief_, u.reading);
  if (map_.cells() <= kMaxKeptBeliefCells) u.belief = belief_;
  u.likeliest = likeliest_of(belief_);
  u.share = belief_[u.likeliest];
  u.robot_cell = loc::cell_index(map_, maze::Cell{arrival.cell.x, arrival.cell.y});
  if (!summary_.localized_at && belief_[u.likeliest] >= summary_.localized_share)
    summary_.localized_at = summary_.updates.size();
  summary_.updates.push_back(std::move(u));
  if (out_ != nullptr) print(summary_.updates.back());
}

void LiveLocalization::print(const LocalizationUpdate &u) const {
  std::string text = u.side ? fmt::format("localize: move {} {}, ", u.move, "NESW"[*u.side])
                            : std::string("localize: the start, ");
  text += fmt::format("the lidar reads {}\n", loc::reading_words(u.reading));
  if (!u.belief.empty()) text += loc::belief_map(map_, u.belief) + loc::belief_grid(map_, u.belief);
  text += fmt::format("most likely: cell {} ({:.3f})\n\n", u.likeliest + 1, u.share);
  *out_ << text;
}

std::string localization_verdict(const LocalizationSummary &s) {
  if (s.updates.empty()) return "no reading was made";
  const LocalizationUpdate &last = s.updates.back();
  const double share = last.share;
  if (share < s.localized_share) {
    return fmt::format("not localized: most likely cell {} holds {:.3f} (below {:g}) after {} moves; the robot is in cell {}",
                       last.likeliest + 1, share, s.localized_share, last.move, last.robot_cell + 1);
  }
  const LocalizationUpdate &first = s.updates[s.localized_at.value_or(s.updates.size() - 1)];
  return fmt::format("cell {} holds {:.3f} after {} moves, first localized at move {} (step {}); the robot is in cell {}{}",
                     last.likeliest + 1, share, last.move, first.move, first.step, last.robot_cell + 1,
                     last.likeliest == last.robot_cell ? "" : " (a wrong cell: the readings or moves misled the filter)");
}

}  // namespace app
