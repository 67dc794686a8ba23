#pragma once
// Inverse sensor models for the robots without a lidar: bumpers, depth rays, an IR
// ring (pie-slice model) and a sonar/IR ring (cone model). Each turns one set of readings
// into marks on the grid; the controller reads the devices, these functions never do.
//
//   bump   p = 0.99999 at the contact point of a pressed bumper; p = 0.3 at the robot's own
//          sub-cell and at the contact points of the bumpers not pressed. Base 10:
//          l(0.99999) = 5.000, l(0.3) = -0.368 (the course numbers).
//   depth  each ray with a reading strictly between 0 and its max range: the hit sub-cell
//          p = 0.99999, the sub-cells the ray crosses before it p = 0.4, the robot's own
//          sub-cell p = 0.3 (base 10: 5.000, -0.176, -0.368). Readings of 0 or max: ignored.
//   pie    a reading d < max is "contacting", else "clear". The clear slice reaches d (see
//          below for noise near max), half-angle beta around the sensor's direction; a
//          contacting reading adds a contact slice reaching d + alpha. Each sub-cell's four
//          corners and centre are tested: a point in the contact slice but not in the clear
//          one makes the sub-cell occupied (p = 0.7), else a point in the clear slice makes
//          it free (p = 0.4). Besides, a sub-cell is occupied when one of the reading's
//          arcs - radii d (1 - 2 eps) ... d (1 + 2 eps) across the slice, where the contact
//          part begins and the obstacle is, within two of the reading's errors (eps is a
//          standard deviation) - passes through its inside (an exact test, not a sample): a
//          reading a little long must not put an outer wall beyond the grid's edge. With 1 m cells, K = 3 or
//          5 and beta = 10 deg no corner or centre ever lies in the 0.1 m contact part beyond
//          a wall 0.4 m ahead (the band sub-cell straddling the wall face has its centre in
//          front of it, its corners outside the 0.14 m wide slice), so the five points alone
//          never mark a wall; the arc lies in exactly that sub-cell. At K = 9 the corners do
//          reach the contact part and the arc adds at most its neighbours across the slice.
//   cone   reading d, beam width sigma (full aperture), distance error eps (a standard deviation):
//          the arc between d(1 - 2 eps) and d(1 + 2 eps) across the beam is occupied (the model's
//          p_occ), the cone inside d(1 - 2 eps) free (p_free); swept at an angular step of half a
//          sub-cell's angular size at that range (and radially at half a sub-cell), so every
//          sub-cell it covers is visited. A reading of nothing seen (is_no_return) frees the cone
//          up to min(d, usable range, 2/3 max) (1 - 2 eps), no arc; a sonar's, only when it looks
//          square to the grid (no_return_tells), else it marks nothing. Both are weighted as in
//          Moravec & Elfes (1985) and Elfes (1989): a point at angle theta off the axis and range r
//          carries p = prior + w (p_model - prior) with w = 1 - (theta / (sigma/2))^2 on the arc
//          and w = (1 - (theta / (sigma/2))^2) (1 - (r / (d (1 - 2 eps)))^2) in the free cone: the
//          model's p on the axis (at the sensor, for free), no information at the edges and where
//          the free cone meets the arc. Why: a wide beam (sonar, 0.4 rad) hears the nearest echo
//          among rays spread over the cone (Webots' sonar), and an IR averages its rays, so a point
//          inside the reading need not be free; unweighted, the cone's edges freed the wall bands
//          beside every corridor the sonar looked along (-0.85 each time against the arc's +0.41
//          once): 15 of lab4x4's 40 sides came out wrong, every one a wall read as open. The arc is
//          sampled at the centres of an odd number of equal angular steps, so a narrow beam (IR,
//          0.03 rad, one step) is marked on its axis and the axis keeps the course numbers.
// pie: a reading within two distance errors of max (>= max (1 - 2 eps)) is clear, and a
// clear slice reaches the reading (1 - eps): the sensor's noise near max range would
// otherwise report phantom contacts, or free a wall just short of max. With the profiles'
// noise (a standard deviation of eps times the value) a nothing-seen reading falls below
// max (1 - eps) one time in six, below max (1 - 2 eps) one time in 44; one phantom contact
// (+0.85) takes two clear slices (-0.41 each) to undo.
// Per scan each sub-cell is updated once; the strongest evidence wins (occupied over the
// robot's own sub-cell over free along a ray; within a level, the larger weight). Increments
// are SensorModel::increment_for(p), i.e. l(p) - l(prior) in the model's base; only the cone
// model marks with weights below 1.

#include <cstddef>
#include <span>
#include <vector>

#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"
#include "mapping/walls.hpp"

namespace sensing {

inline constexpr double kBumpOccupiedP = 0.99999;
inline constexpr double kBumpFreeP = 0.3;
inline constexpr double kDepthHitP = 0.99999;
inline constexpr double kDepthRayP = 0.4;
inline constexpr double kDepthRobotP = 0.3;
inline constexpr double kPieOccupiedP = 0.7;
inline constexpr double kPieFreeP = 0.4;
// pie: a reading d is a contact when d (1 + n eps) < max (1 - n eps), n = kPieNoReturnErrors:
// it lies more than n of its own errors from a no-return reading; otherwise it is clear.
inline constexpr double kPieNoReturnErrors = 2.0;
// pie: a contact counts only when the slice's axis between d (1 - n eps) and d (1 + n eps)
// comes within kPieSideSlack cell sizes of a cell side, where walls are; otherwise the reading
// (rays averaged across a post's edge) is ignored.
inline constexpr double kPieSideSlack = 0.05;
// cone: readings whose distance error eps d exceeds kConeUsableError cell sizes are beyond the
// usable range (sonar, eps 6.6 %: 2.27 m with 1 m cells; the 1.5 m IR is never cut).
inline constexpr double kConeUsableError = 0.15;
// cone: a reading of nothing seen frees the cone no farther than this fraction of max range,
// as the pie's usable range (RangeModelOptions::pie_usable_fraction): the IR's wall 1.40 m
// ahead, in the band a cell beyond, reads as nothing seen (1.33 m or more) 24 times in 25.
inline constexpr double kConeNoReturnReach = 2.0 / 3.0;
// cone: the occupied arc spans d (1 - n eps) ... d (1 + n eps), n = kConeArcErrors.
inline constexpr double kConeArcErrors = 2.0;

// One bumper as read: where it touches (robot centre + mounting offset along its angle).
struct BumpReading {
  mapping::Point contact;
  bool pressed = false;
};

// One range reading in the world frame.
struct RangeReading {
  mapping::Point origin;             // the sensor, m
  double angle_rad = 0.0;   // its direction in the world, rad
  double range_m = 0.0;     // the reading, m
  double max_range_m = 0.0; // readings at or beyond this are "nothing seen"
  double aperture_rad = 0.0;  // full beam width (cone model)
  double range_error = 0.0;   // relative distance error eps (cone model)
  // A sonar (DistanceSensor::getType() SONAR): a surface at more than 22.5 deg to the beam
  // sends no echo back, so a reading of nothing seen says nothing about the cone.
  bool echo_can_be_lost = false;
};

// A sonar ray meeting a surface at more than this angle of incidence sends no echo back
// (Webots' DistanceSensor reference, type "sonar").
inline constexpr double kSonarEchoIncidence_rad = 0.39269908169872414;  // pi / 8
// Whether a reading of nothing seen tells of the cone: always for a sensor that cannot lose
// an echo; for a sonar only when it looks square to the grid (its axis within pi/8 - half its
// aperture of a grid axis), so that every ray would meet a wall on a cell side, the only
// place walls stand, at an incidence that echoes. A sonar at a slant to the grid hears
// nothing whether or not a wall is there.
bool no_return_tells(const RangeReading &r);

// Whether a reading is "nothing seen": within kPieNoReturnErrors of its own errors of max
// range (d (1 + n eps) >= max (1 - n eps)); the sensor's noise, a fraction eps of the value,
// puts a nothing-seen reading below max half the time.
bool is_no_return(const RangeReading &r);

struct RangeModelOptions {
  double pie_half_angle_rad = 0.17453292519943295;  // beta, --pie-beta (deg on the command line)
  double pie_contact_m = 0.1;                        // alpha, --pie-alpha
  // The clear slice ends at this fraction of max range, the sensor's usable range (gmapping's
  // maxUrange): beyond 1 m the 10 deg slice of a 1.5 m IR takes in the inner corners of the
  // side bands of the corridor ahead and the near corners of the next cell's far band, and
  // freed them on every pass. 1 keeps the course's whole slice.
  double pie_usable_fraction = 2.0 / 3.0;
};

// Throws common::InputError when beta is not in (0, 90 deg), alpha not positive or the usable
// fraction not in (0, 1].
void validate(const RangeModelOptions &options);

// Marks with their own probabilities, gathered per scan: each sub-cell is updated once with
// the mark of the lowest level (level 0 strongest) and, among those, the largest weight. A
// mark of weight w in (0, 1] stands for p = prior + w (p_level - prior): the level's own p
// at weight 1, the prior (no update) as w goes to 0. Marks outside the grid, or of weight
// 0 or less, are ignored.
class LeveledUpdate {
 public:
  explicit LeveledUpdate(std::vector<double> level_p) : level_p_(std::move(level_p)) {}
  void mark(const mapping::OccupancyGrid &grid, mapping::SubCell s, int level, double weight = 1.0);
  void mark(const mapping::OccupancyGrid &grid, mapping::Point p, int level, double weight = 1.0);
  // Applies l += increment_for(p of the level) once per marked sub-cell; returns the count.
  std::size_t apply(mapping::OccupancyGrid &grid, const mapping::SensorModel &model);
  bool empty() const { return marks_.empty(); }

 private:
  std::vector<double> level_p_;
  struct Mark {
    std::size_t index;
    int level;
    double weight;
  };
  std::vector<Mark> marks_;
};

// Levels: 0 occupied 0.99999, 1 free 0.3.
LeveledUpdate make_bump_update();
void mark_bumps(const mapping::OccupancyGrid &grid, mapping::Point robot, std::span<const BumpReading> bumpers,
                LeveledUpdate &update);

// Levels: 0 hit 0.99999, 1 robot 0.3, 2 along the ray 0.4.
LeveledUpdate make_depth_update();
void mark_depth(const mapping::OccupancyGrid &grid, mapping::Point robot, std::span<const RangeReading> rays,
                LeveledUpdate &update);

// Levels: 0 occupied 0.7, 1 free 0.4.
LeveledUpdate make_pie_update();
void mark_pie(const mapping::OccupancyGrid &grid, const RangeModelOptions &options,
              std::span<const RangeReading> readings, LeveledUpdate &update);

// What readings taken in cell c say of its side h, as the lidar's read_cell_side does for a
// scan: a reading whose axis points within kFacingSide_rad of h and that returns closer than
// the side's line plus kRangeSideMargin cells reads a wall; one that returns farther, or
// sees nothing, reads open (a sonar's lost echo says nothing); unknown when no reading
// faces h. The robot reads a side again when the grid calls it open but this says wall.
inline constexpr double kFacingSide_rad = 0.1;
inline constexpr double kRangeSideMargin = 0.25;
mapping::SideState read_range_side(const mapping::OccupancyGrid &grid, std::span<const RangeReading> readings,
                                   mapping::Cell c, mapping::Heading h);

// Levels: 0 occupied (p_occ), 1 free (p_free) of the sensor model.
LeveledUpdate make_cone_update(const mapping::SensorModelOptions &sensor);
void mark_cone(const mapping::OccupancyGrid &grid, std::span<const RangeReading> readings,
               LeveledUpdate &update);

}  // namespace sensing
