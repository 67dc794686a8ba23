#pragma once
// Usage errors in the program's own words, composed from the command tree, never by
// rewriting CLI11's messages:
//
//   run --prior abc      ->  --prior needs a number (got 'abc')      (check_values_ourselves)
//   run --out ""         ->  --out must not be empty                 (check_values_ourselves)
//   run --prior          ->  --prior needs a value                   (ArgumentMismatch)
//   run --clamp 1        ->  --clamp needs 2 values (got 1)          (ArgumentMismatch)
//   run --sede 3         ->  run has no option --sede; did you mean --seed?   (ExtrasError)
//   rnu                  ->  unknown command 'rnu'; did you mean run?         (ExtrasError)
//   run --quiet=maybe    ->  --quiet is a flag: it takes no value, or true or false (got 'maybe')
//                                                                    (ConversionError)
//   convert x.txt        ->  convert needs OUT                       (RequiredError)
//   run -out DIR         ->  run has no option -out; did you mean --out? (one_dash_long_option)
//   maze8x8.txt          ->  unknown command 'maze8x8.txt'; to map that world: maze_mapper run maze8x8.txt
//
// A value's check throws common::InputError ("error: MESSAGE", exit 2) from inside CLI11's
// parse; the other errors are CLI11's exceptions, told by their type and the tree's state.
// Without the leading "error: ".

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace app {

// A validator for `option` whose check returns "" or what is wrong with the value ("must be
// a whole number from 0 ..."); a wrong value throws common::InputError("OPTION must be ...").
CLI::Validator usage_check(const std::string &option, std::function<std::string(const std::string &)> check);

// Every option of the tree that takes values refuses an empty one ("" would read as the
// option left out), and a numeric one refuses a value that does not read as its type asks
// (common/parse_number.hpp; a FLOAT may be inf or nan, which its own check words).
void check_values_ourselves(CLI::App &command);

// The words: the command line as parsed (without the program's name), which tell the
// option left short of values at the end.
std::string describe_usage_error(const CLI::App &cli, const CLI::ParseError &error,
                                 const std::vector<std::string> &words);

// A long option typed with one dash (`run -out DIR`, which CLI11 would read as `-o ut`):
// "run has no option -out; did you mean --out? ..." for the first such word of the command
// line (the words after the program's name, up to a lone `--`), "" when there is none.
std::string one_dash_long_option(const CLI::App &cli, const std::vector<std::string> &words);

// The names within a small edit distance of `typed` (transpositions count one), the
// closest first: for "--sede" among --seed, --speed, --step: {"--seed"}. A prefix of
// exactly one name is that name ("--max" -> "--max-steps"). Empty when nothing is close.
std::vector<std::string> close_names(std::string_view typed, const std::vector<std::string> &names);

}  // namespace app
