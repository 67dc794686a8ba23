#pragma once
// --help as it reads in a terminal: every line within the width (COLUMNS, else the terminal's,
// else 80), text wrapped at words, a command's options in groups (World; Robot and model;
// Exploration; Faults; Output; then the rest), each option with the name of its value and no
// library leftovers (CLI11's "{false}", "Excludes:"), the usage line naming what is required,
// and the command's examples last (its footer).

#include <cstddef>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

namespace app {

// The help's width: COLUMNS when it is a number from 40 to 500, else the width of the
// terminal on standard output, else 80 (a pipe).
std::size_t help_width();

// `text` wrapped at spaces to lines of at most `width` columns (a word longer than that stands
// alone), each line after the first, and the first too when `indent_first`, indented by
// `indent` spaces. Newlines in `text` are kept. Columns are counted in UTF-8 code points.
std::string wrap_words(std::string_view text, std::size_t width, std::size_t indent, bool indent_first);

// The option groups in the order --help lists them.
inline constexpr const char *kWorldGroup = "World";
inline constexpr const char *kRobotGroup = "Robot and model";
inline constexpr const char *kExplorationGroup = "Exploration";
inline constexpr const char *kFaultsGroup = "Faults";
inline constexpr const char *kOutputGroup = "Output";

// Shows an argument or option as required in the usage line when the command checks it itself
// (CLI11's required() would misread some command lines, as scan's WORLD and --pose).
void show_as_required(CLI::Option &option);

// Puts every option of `root` and its subcommands in its group (a table from option names to
// groups; an option it does not name stays in CLI11's "Options" group, listed last) and gives
// them all the readable formatter, and each command its examples (a table by command path).
// Call once the commands are added.
void use_readable_help(CLI::App &root);

}  // namespace app
