#pragma once
// The command line's reference, generated from the command definitions themselves (the CLI11
// App tree add_commands builds), so that the man page and the shell completions list every
// subcommand and option there is: a roff man page (man 1), and bash, zsh and fish
// completion scripts. The build runs `maze_mapper __reference man|bash|zsh|fish` and installs
// the results; tests check every option of every command is in each.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace app {

// The hidden subcommand that prints the reference; not listed by --help nor in the reference.
inline constexpr const char *kReferenceCommand = "__reference";

// A command of the tree as the reference shows it: its path from the top ("" for the
// program, "run", "demo 1d"), its description, its options and subcommands. Hidden commands
// (CLI11's empty group) are left out, with their subtrees.
struct CommandNode {
  std::string path;
  const CLI::App *app = nullptr;
};

// The program and every visible command below it, depth first in --help's order.
std::vector<CommandNode> visible_commands(const CLI::App &root);

// The option's names as typed ("--robot", "-o", "--output"), long names first.
std::vector<std::string> option_names(const CLI::Option &option);

// Whether the option takes a value (a flag does not).
bool takes_value(const CLI::Option &option);

// What the option's value is called: the capitals its description starts with ("NAME or
// FILE.json: ..." -> "NAME or FILE.json", "e|10: ..." -> "e|10"), else its type: N (whole
// numbers), X (numbers), NAME (words); "" for a flag.
std::string value_name(const CLI::Option &option);

std::string man_page(const CLI::App &root, const std::string &version);
std::string bash_completion(const CLI::App &root);
std::string zsh_completion(const CLI::App &root);
std::string fish_completion(const CLI::App &root);

// Registers the hidden subcommand on `root` (the program's App).
void add_reference_command(CLI::App &root);

}  // namespace app
