// The help lines' lists of set-ups and robots (app/run/option_fields.hpp).

#include <algorithm>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "app/run/option_fields.hpp"
#include "maze/sim/profile.hpp"
#include "sensing/setups.hpp"

namespace app {

namespace {

// The set-ups' names grouped by `key` ("cell, ray (a lidar); bump (bumpers); ...") or the
// names sharing one key.
template <typename Key>
std::vector<std::pair<std::string_view, std::string>> grouped(Key key, std::string_view separator) {
  std::vector<std::pair<std::string_view, std::string>> groups;
  for (const sensing::SetUp &s : sensing::setups()) {
    const auto same = [&](const auto &g) { return g.first == key(s); };
    auto group = std::find_if(groups.begin(), groups.end(), same);
    if (group == groups.end()) {
      groups.emplace_back(key(s), std::string(s.name));
    } else {
      group->second += fmt::format("{}{}", separator, s.name);
    }
  }
  return groups;
}

}  // namespace

std::string models_by_device() {
  std::string text;
  for (const auto &[devices, names] : grouped([](const sensing::SetUp &s) { return s.devices(); }, ", ")) {
    text += fmt::format("{}{} ({})", text.empty() ? "" : "; ", names, devices);
  }
  return text;
}

std::string default_robots() {
  std::string text;
  std::string others;
  for (const auto &[robot, names] : grouped([](const sensing::SetUp &s) { return s.default_robot; }, " and ")) {
    if (text.empty()) {
      text = robot;
    } else {
      others += fmt::format("{}{} for {}", others.empty() ? "" : ", ", robot, names);
    }
  }
  return others.empty() ? text : fmt::format("{}; {}", text, others);
}

std::string robot_names() {
  std::string names;
  for (const maze::sim::RobotProfile &p : maze::sim::profiles()) names += (names.empty() ? "" : ", ") + p.name;
  return names;
}

}  // namespace app
