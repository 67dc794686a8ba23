#include <doctest/doctest.h>

#include <set>
#include <string>

#include "common/error.hpp"
#include "maze/sim/profile.hpp"
#include "sensing/setups.hpp"

// The table of set-ups: every model has one row, and each row's facts hold together.

namespace {

bool has_devices(const maze::sim::RobotProfile &p, const sensing::SetUp &s) {
  if (s.reads_lidar()) return !p.lidars.empty();
  return s.reads_bumpers() ? !p.bumpers.empty() : !p.distance_sensors.empty();
}

}  // namespace

TEST_CASE("setups: one row per model, names unique and parsed back") {
  std::set<std::string> names;
  for (const sensing::SetUp &s : sensing::setups()) {
    CAPTURE(s.name);
    CHECK(names.insert(std::string(s.name)).second);
    CHECK(&sensing::setup(s.kind) == &s);
    CHECK(sensing::parse_model(s.name) == s.kind);
    CHECK(sensing::to_string(s.kind) == s.name);
    CHECK_FALSE(s.description.empty());
  }
  CHECK(names.size() == 6);
  CHECK(sensing::setup_names() == "cell, ray, bump, depth, pie or cone");
  try {
    sensing::parse_model("sonar");
    FAIL("parsed");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic() == "error: unknown --model 'sonar' (choose cell, ray, bump, depth, pie or cone)");
  }
}

TEST_CASE("setups: the default robot of each has the devices it reads") {
  for (const sensing::SetUp &s : sensing::setups()) {
    CAPTURE(s.name);
    CHECK(has_devices(maze::sim::find_profile(std::string(s.default_robot)), s));
  }
}

TEST_CASE("setups: the lidar models mark with the sensor model, the range and bump models with their levels") {
  for (const sensing::SetUp &s : sensing::setups()) {
    CAPTURE(s.name);
    CHECK(s.reads_lidar() == (s.make_update == nullptr));
    // Whatever can read a side from where it stands (a lidar, a range ring) confirms it.
    CHECK((s.arrival == sensing::Arrival::resolve_and_confirm) ==
          (s.reads_lidar() || (s.reads_ranges() && s.kind != sensing::ModelKind::depth)));
    // Fixed course numbers and --p-free/--p-occ exclude each other.
    CHECK(s.fixed.has_value() != s.uses(sensing::kProbabilities));
  }
  mapping::SensorModelOptions sensor;
  sensor.p_free = 0.2;
  sensor.p_occ = 0.8;
  const sensing::MarkProbabilities pie = sensing::probabilities_in_effect(sensing::setup(sensing::ModelKind::pie), sensor);
  CHECK(pie.p_free == 0.4);
  CHECK(pie.p_occ == 0.7);
  const sensing::MarkProbabilities depth =
      sensing::probabilities_in_effect(sensing::setup(sensing::ModelKind::depth), sensor);
  CHECK(depth.p_robot == 0.3);
  const sensing::MarkProbabilities cone = sensing::probabilities_in_effect(sensing::setup(sensing::ModelKind::cone), sensor);
  CHECK(cone.p_free == 0.2);
  CHECK(cone.p_occ == 0.8);
  CHECK(sensing::setup(sensing::ModelKind::ray).uses(sensing::kHitDepth));
  CHECK_FALSE(sensing::setup(sensing::ModelKind::cell).uses(sensing::kHitDepth));
  CHECK(sensing::option_name(sensing::kPieBeta) == "--pie-beta");
}
