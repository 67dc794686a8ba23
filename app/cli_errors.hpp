#pragma once
// CLI11's usage errors in the program's own words, where its wording is unclear:
//   Could not convert: --prior = abc      ->  --prior needs a number (got 'abc')
//   --prior: 1 required FLOAT missing     ->  --prior needs a value
//   --clamp: At least 2 required but received 1  ->  --clamp needs 2 values (got 1)
//   --seed: must be ... (our own checks)  ->  --seed must be ...
// Any other error keeps CLI11's text. Without the leading "error: ".

#include <string>

#include <CLI/CLI.hpp>

namespace app {

std::string describe_usage_error(const CLI::App &cli, const CLI::ParseError &error);

}  // namespace app
