// moveForward N as one ramped leg with the walls the robot senses (--walls sensed, the
// default): the lidar looks down the straight, so the cells it sees open are driven as with
// --walls truth; a wall it sees ends the leg before it (crash, as before), and a straight
// past its reach is driven in legs as far as it sees.

#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/mms/mms_session.hpp"

namespace {

const std::string kLegScripts = std::string(TEST_DATA_DIR) + "/mms/";

struct LegRobot {
  std::string name;  // empty: mms's default (hambot)
  std::optional<double> cell_size_m;
};

app::MmsRun drive_mms(const std::string &world, const LegRobot &robot, app::MmsWalls walls, std::vector<std::string> command) {
  app::RunOptions options;
  options.world = world;
  options.world_overrides.cell_size_m = robot.cell_size_m;
  if (!robot.name.empty()) options.robot = robot.name;
  options.output.quiet = true;
  app::MmsOptions mms;
  mms.command = {"sh"};
  mms.command.insert(mms.command.end(), command.begin(), command.end());
  mms.walls = walls;
  std::ostringstream out;
  return app::run_mms_world(options, mms, out);
}

const std::string kLegOpenRoom = std::string(WORLDS_DIR) + "/open_room6x6.txt";

// Simulated seconds of `moveForward` with these counts from the start of the open room, less
// those of a run that does not move; checks the five cells were driven without a crash.
double forward_leg_s(const LegRobot &robot, app::MmsWalls walls, std::vector<std::string> counts) {
  std::vector<std::string> command{kLegScripts + "forward.sh"};
  command.insert(command.end(), counts.begin(), counts.end());
  const app::MmsRun standing = drive_mms(kLegOpenRoom, robot, walls, {kLegScripts + "forward.sh"});
  const app::MmsRun run = drive_mms(kLegOpenRoom, robot, walls, command);
  INFO(run.mms.message);
  CHECK(run.mms.end == app::MmsEnd::exited);
  CHECK(run.summary.moves == 5);
  CHECK(run.mms.crashes == 0);
  CHECK(run.mms.stats.total_distance() == 5);
  return run.summary.sim_time_s - standing.summary.sim_time_s;
}

void check_sensed_leg_as_truth(const LegRobot &robot) {
  const double truth_s = forward_leg_s(robot, app::MmsWalls::truth, {"5"});
  const double sensed_s = forward_leg_s(robot, app::MmsWalls::sensed, {"5"});
  const double five_moves_s = forward_leg_s(robot, app::MmsWalls::sensed, {"1", "1", "1", "1", "1"});
  CAPTURE(truth_s);
  CAPTURE(sensed_s);
  CAPTURE(five_moves_s);
  CHECK(std::abs(sensed_s - truth_s) <= 0.02 * truth_s);
  CHECK(sensed_s < 0.8 * five_moves_s);
}

}  // namespace

TEST_CASE("mms: moveForward 5 over cells the lidar sees open ramps once with sensed walls, as with truth") {
  SUBCASE("the default robot (hambot), 1 m cells") { check_sensed_leg_as_truth({"", std::nullopt}); }
  SUBCASE("the micromouse, 0.18 m cells") { check_sensed_leg_as_truth({"micromouse", 0.18}); }
}

TEST_CASE("mms: moveForward 5 towards a wall three cells on stops before it, crash, in one leg in both wall modes") {
  const std::string world = std::string(TEST_DATA_DIR) + "/worlds/wall_ahead6x6.txt";
  const LegRobot hambot{"", std::nullopt};
  const app::MmsRun standing = drive_mms(world, hambot, app::MmsWalls::truth, {kLegScripts + "forward.sh"});
  std::vector<double> leg_s;
  for (const app::MmsWalls walls : {app::MmsWalls::truth, app::MmsWalls::sensed}) {
    const app::MmsRun run = drive_mms(world, hambot, walls, {kLegScripts + "wall_ahead.sh"});
    INFO(run.mms.message);
    CHECK(run.mms.end == app::MmsEnd::exited);  // every answer as expected (crash, wall, 5)
    CHECK(run.summary.moves == 3);
    CHECK(run.mms.crashes == 1);
    CHECK(run.summary.visited == 4);
    leg_s.push_back(run.summary.sim_time_s - standing.summary.sim_time_s);
  }
  CAPTURE(leg_s[0]);
  CAPTURE(leg_s[1]);
  CHECK(std::abs(leg_s[1] - leg_s[0]) <= 0.02 * leg_s[0]);
}

TEST_CASE("mms: a straight past the lidar's reach is driven in legs as far as it sees, the five cells all the same") {
  // The micromouse's lidar reaches 1 m: from a cell's centre, in 0.5 m cells, the sides of two
  // cells on (0.25 and 0.75 m away, with the quarter-cell margin), not the third's.
  const LegRobot short_sight{"micromouse", 0.5};
  const double truth_s = forward_leg_s(short_sight, app::MmsWalls::truth, {"5"});
  const double sensed_s = forward_leg_s(short_sight, app::MmsWalls::sensed, {"5"});
  const double five_moves_s = forward_leg_s(short_sight, app::MmsWalls::sensed, {"1", "1", "1", "1", "1"});
  CAPTURE(truth_s);
  CAPTURE(sensed_s);
  CAPTURE(five_moves_s);
  CHECK(sensed_s > 1.05 * truth_s);
  CHECK(sensed_s < 0.95 * five_moves_s);
}
