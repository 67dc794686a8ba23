#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "app/run/option_values.hpp"
#include "common/error.hpp"

TEST_CASE("a number list reads comma-separated numbers with blanks around each") {
  CHECK(app::parse_number_list("1, 1.5,0.8", "--readings") == std::vector<double>{1.0, 1.5, 0.8});
  CHECK(app::parse_number_list(" 7 ", "--readings") == std::vector<double>{7.0});
  CHECK(app::parse_number_list("3,5", "--cells", 2) == std::vector<double>{3.0, 5.0});
  // Infinite and NaN items are numbers here: each option checks its own range.
  CHECK(std::isinf(app::parse_number_list("1,inf", "--boundary")[1]));
}

TEST_CASE("a number list's errors name the option, the item and what was typed") {
  CHECK_THROWS_WITH_AS(app::parse_number_list("1,x,3", "--readings"), "--readings item 2 is not a number (got 'x')",
                       common::InputError);
  CHECK_THROWS_WITH_AS(app::parse_number_list("1,,3", "--mounts"), "--mounts item 2 is not a number (got '')",
                       common::InputError);
  CHECK_THROWS_WITH_AS(app::parse_number_list("", "--cells", 2), "--cells item 1 is not a number (got '')",
                       common::InputError);
  CHECK_THROWS_WITH_AS(app::parse_number_list("1,2,3", "--cells", 2), "--cells needs 2 numbers (got 3)",
                       common::InputError);
}

TEST_CASE("a pose is Xm,Ym,YAW with YAW in degrees, or with its unit, or a heading letter") {
  std::vector<std::string> warnings;
  const app::PoseArgument degrees = app::parse_pose("0.5m,1.5m,90", "--pose", warnings);
  CHECK(degrees.x_m == 0.5);
  CHECK(degrees.y_m == 1.5);
  CHECK(degrees.yaw_deg == 90.0);
  CHECK(degrees.yaw_rad == doctest::Approx(1.5707963267948966));
  CHECK(app::parse_pose("0.5m,1.5m,90deg", "--pose", warnings).yaw_deg == 90.0);
  CHECK(app::parse_pose("0.5m,1.5m,S", "--pose", warnings).yaw_deg == 270.0);
  const app::PoseArgument centimetres = app::parse_pose("50cm, 150cm ,0", "--pose", warnings);
  CHECK(centimetres.x_m == 0.5);
  CHECK(centimetres.y_m == 1.5);
  const app::PoseArgument radians = app::parse_pose("0.5m,1.5m,1.5707963267948966rad", "--pose", warnings);
  CHECK(radians.yaw_rad == 1.5707963267948966);
  CHECK(radians.yaw_deg == doctest::Approx(90.0));
  CHECK(warnings.empty());
  // 90 "radians" is 14 turns: it was meant as degrees.
  (void)app::parse_pose("0.5m,1.5m,90rad", "--pose", warnings);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0] == "warning: --pose YAW 90rad is 5156.62 degrees, more than a turn; for 90 degrees write --pose "
                       "0.5m,1.5m,90");
  CHECK_THROWS_WITH_AS(app::parse_pose("0.5m,1.5m", "--pose", warnings), "--pose needs 3 numbers (got 2)",
                       common::InputError);
  CHECK_THROWS_WITH_AS(app::parse_pose("0.5m,infm,0", "--pose", warnings), "--pose must be three finite numbers",
                       common::InputError);
  CHECK_THROWS_WITH_AS(app::parse_pose("0.5m,1.5km,0", "--pose", warnings), "--pose item 2 is not a number (got '1.5km')",
                       common::InputError);
  CHECK_THROWS_WITH_AS(app::parse_pose("0.5m,1.5m,Q", "--pose", warnings), "--pose item 3 is not a number (got 'Q')",
                       common::InputError);
}

TEST_CASE("a pose's X,Y without a unit is the old spelling: read as metres, with a warning") {
  std::vector<std::string> warnings;
  const app::PoseArgument pose = app::parse_pose("1.5,2.5,270", "--pose", warnings);
  CHECK(pose.x_m == 1.5);
  CHECK(pose.y_m == 2.5);
  CHECK(pose.yaw_deg == 270.0);
  CHECK(warnings == std::vector<std::string>{"warning: --pose 1.5,2.5,270 is the old spelling; write --pose "
                                             "1.5m,2.5m,270 (the old one goes in the next release)"});
}

TEST_CASE("a start's YAW may be left out where the option allows it") {
  std::vector<std::string> warnings;
  const app::PoseArgument place = app::parse_pose("0.5m,1.5m", "--start", warnings, app::PoseYaw::optional);
  CHECK(place.x_m == 0.5);
  CHECK_FALSE(place.yaw_given);
  CHECK(app::parse_pose("0.5m,1.5m,45", "--start", warnings, app::PoseYaw::optional).yaw_deg == 45.0);
  CHECK(warnings.empty());
  CHECK_THROWS_WITH_AS(app::parse_pose("0.5m", "--start", warnings, app::PoseYaw::optional),
                       "--start needs 2 or 3 numbers (got 1)", common::InputError);
}

TEST_CASE("a length carries its unit m or cm, and comes back exactly in the unit it was typed in") {
  const std::optional<app::Length> cm = app::length_of("7cm");
  REQUIRE(cm.has_value());
  CHECK(cm->unit == app::LengthUnit::cm);
  CHECK(app::centimetres(*cm) == 7.0);
  CHECK(app::metres(*cm) == 0.07);
  const std::optional<app::Length> m = app::length_of("0.25m");
  REQUIRE(m.has_value());
  CHECK(app::metres(*m) == 0.25);
  CHECK(app::centimetres(*m) == 25.0);
  const std::optional<app::Length> bare = app::length_of("10");
  REQUIRE(bare.has_value());
  CHECK(bare->unit == app::LengthUnit::none);
  CHECK(app::metres(*bare) == 10.0);
  CHECK(app::centimetres(*bare, app::LengthUnit::cm) == 10.0);
  CHECK_FALSE(app::length_of("10 km").has_value());
  CHECK_FALSE(app::length_of("m").has_value());
}
