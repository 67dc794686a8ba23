#pragma once
// CLI11's usage errors in the program's own words, where its wording is unclear:
//   Could not convert: --prior = abc      ->  --prior needs a number (got 'abc')
//   --prior: 1 required FLOAT missing     ->  --prior needs a value
//   --clamp: At least 2 required but received 1  ->  --clamp needs 2 values (got 1)
//   --seed: must be ... (our own checks)  ->  --seed must be ...
//   The following argument was not expected: --sede
//                                         ->  run has no option --sede; did you mean --seed?
//   The following argument was not expected: rnu
//                                         ->  unknown command 'rnu'; did you mean run?
// Any other error keeps CLI11's text. Without the leading "error: ".

#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace app {

std::string describe_usage_error(const CLI::App &cli, const CLI::ParseError &error);

// The names within a small edit distance of `typed` (transpositions count one), the
// closest first: for "--sede" among --seed, --speed, --step: {"--seed"}. A prefix of
// exactly one name is that name ("--max" -> "--max-steps"). Empty when nothing is close.
std::vector<std::string> close_names(std::string_view typed, const std::vector<std::string> &names);

}  // namespace app
