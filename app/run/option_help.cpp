// The help lines of the run's options registered by their own code, one help line for any
// run option, and the lists of set-ups and robots the lines name (app/run/option_fields.hpp).

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "app/run/option_fields.hpp"
#include "common/random.hpp"
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

namespace {

// The help of the run's options registered by their own code (their arity or checks are
// their own; app/cli registers them with these words).
struct OwnHelp {
  std::string_view flag;
  std::string (*help)();
};

const OwnHelp kOwnHelp[] = {
    {"--seed",
     [] {
       return fmt::format("N: seed of the sensor noise, the faults, a random start, wander's turns and a Python "
                          "controller's random module (default {})",
                          common::kDefaultSeed);
     }},
    {"--max-steps",
     [] {
       return std::string(
           "N: stop after N control steps, a Python controller's counted in basic time steps (default 1000 a maze "
           "cell, at least 100000; in metres 2000000; a Python controller 100000)");
     }},
    {"--clamp",
     [] {
       return std::string(
           "MIN MAX: hold log-odds within MIN and MAX, either side of the prior's (OctoMap: -2 3.5) (default none)");
     }},
    {"--out",
     [] {
       return std::string(
           "DIR: write the run's files there: summary.json, trace.csv, map.png, truth.png, replay.html and the "
           "kind's own (docs/output.md)");
     }},
};

template <typename Concern>
std::optional<std::string> field_help(std::string_view flag, const Concern &defaults) {
  for (const OptionField<Concern> &field : option_fields<Concern>()) {
    if (field.flag == flag && field.help != nullptr) return field.help(defaults);
  }
  return std::nullopt;
}

}  // namespace

std::string option_help(std::string_view flag) {
  for (const OwnHelp &own : kOwnHelp) {
    if (own.flag == flag) return own.help();
  }
  const RunOptions d;
  for (const std::optional<std::string> &help :
       {field_help(flag, d), field_help(flag, d.world_overrides), field_help(flag, d.model), field_help(flag, d.sensor),
        field_help(flag, d.range_model), field_help(flag, d.simulation), field_help(flag, d.plan),
        field_help(flag, d.output), field_help(flag, d.metres)}) {
    if (help) return *help;
  }
  throw std::logic_error("no run option " + std::string(flag));
}

}  // namespace app
