#pragma once
// The values the shell completions offer, read from the program's own lists: the strategies
// (explore::strategy_table), the models (sensing::setups), the built-in robots
// (maze::sim::profiles), the --color words (kColorWords) and the shipped worlds.

#include <string>
#include <string_view>
#include <vector>

namespace app {

// The options whose values the completions offer as words.
inline constexpr std::string_view kWordValuedFlags[] = {"--strategy", "--model", "--robot", "--color"};

// The words option `flag` ("--strategy", "--model", "--robot", "--color") takes, in the
// order its help names them; empty for an option whose value is a file or a number.
std::vector<std::string> option_value_words(std::string_view flag);

// The shipped worlds' names without their extensions (lab4x4, maze8x8, ...), as a WORLD
// argument takes them, sorted and each once; empty when the program finds no shipped worlds.
std::vector<std::string> shipped_world_names();

}  // namespace app
