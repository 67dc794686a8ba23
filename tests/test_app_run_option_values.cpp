#include <doctest/doctest.h>

#include <cmath>
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

TEST_CASE("a pose is X,Y,YAW with YAW in degrees, or with its unit") {
  std::vector<std::string> warnings;
  const app::PoseArgument degrees = app::parse_pose("0.5,1.5,90", "--pose", warnings);
  CHECK(degrees.x_m == 0.5);
  CHECK(degrees.y_m == 1.5);
  CHECK(degrees.yaw_deg == 90.0);
  CHECK(degrees.yaw_rad == doctest::Approx(1.5707963267948966));
  CHECK(app::parse_pose("0.5,1.5,90deg", "--pose", warnings).yaw_deg == 90.0);
  const app::PoseArgument radians = app::parse_pose("0.5,1.5,1.5707963267948966rad", "--pose", warnings);
  CHECK(radians.yaw_rad == 1.5707963267948966);
  CHECK(radians.yaw_deg == doctest::Approx(90.0));
  CHECK(warnings.empty());
  // 90 "radians" is 14 turns: it was meant as degrees.
  (void)app::parse_pose("0.5,1.5,90rad", "--pose", warnings);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].find("more than a turn") != std::string::npos);
  CHECK(warnings[0].find("--pose 0.5,1.5,90") != std::string::npos);
  CHECK_THROWS_WITH_AS(app::parse_pose("0.5,1.5", "--pose", warnings), "--pose needs 3 numbers (got 2)",
                       common::InputError);
  CHECK_THROWS_WITH_AS(app::parse_pose("0.5,inf,0", "--pose", warnings), "--pose must be three finite numbers",
                       common::InputError);
}
