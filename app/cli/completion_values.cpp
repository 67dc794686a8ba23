#include "app/cli/completion_values.hpp"

#include <algorithm>

#include "app/run/shipped_worlds.hpp"
#include "app/run/terminal.hpp"
#include "explore/strategies.hpp"
#include "sensing/setups.hpp"
#include "maze/sim/profile.hpp"

namespace app {

std::vector<std::string> option_value_words(std::string_view flag) {
  std::vector<std::string> words;
  if (flag == "--strategy") {
    for (const explore::StrategyRow &row : explore::strategy_table()) words.emplace_back(row.name);
  } else if (flag == "--model") {
    for (const sensing::SetUp &setup : sensing::setups()) words.emplace_back(setup.name);
  } else if (flag == "--robot") {
    for (const maze::sim::RobotProfile &profile : maze::sim::profiles()) words.push_back(profile.name);
  } else if (flag == "--color") {
    for (const ColorWord &w : kColorWords) words.emplace_back(w.word);
  }
  return words;
}

std::vector<std::string> shipped_world_names() {
  std::vector<std::string> names;
  for (const std::filesystem::path &file : shipped_world_files()) names.push_back(file.stem().string());
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

}  // namespace app
