// maze_mapper compare [WORLD] --subcells K1,K2,... [options]: the same world at several
// resolutions, maps and summaries side by side.

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/run.hpp"
#include "app/run_cli.hpp"
#include "app/terminal.hpp"
#include "commands.hpp"
#include "common/error.hpp"

namespace app {
namespace {

// Display width of UTF-8 text: code points (the map's arrows are one column each).
std::size_t display_width(const std::string &text) {
  std::size_t n = 0;
  for (const char ch : text) n += (static_cast<unsigned char>(ch) & 0xC0) != 0x80 ? 1 : 0;
  return n;
}

std::vector<std::string> split(const std::string &text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return parts;
}

// "3,5" -> {3, 5}, each K checked.
std::vector<int> parse_ks(const std::string &subcells) {
  std::vector<int> ks;
  for (const std::string &part : split(subcells, ',')) {
    char *end = nullptr;
    const long k = std::strtol(part.c_str(), &end, 10);
    if (part.empty() || *end != '\0') {
      throw common::InputError(fmt::format("--subcells must be a list like 3,5 (got '{}')", subcells));
    }
    validate_subcells(static_cast<int>(k));
    ks.push_back(static_cast<int>(k));
  }
  return ks;
}

// The columns side by side, 3 blanks apart, trailing blanks dropped.
void print_columns(const std::vector<std::vector<std::string>> &columns, std::ostream &out) {
  std::vector<std::size_t> widths;
  std::size_t rows = 0;
  for (const auto &column : columns) {
    std::size_t width = 0;
    for (const std::string &line : column) width = std::max(width, display_width(line));
    widths.push_back(width);
    rows = std::max(rows, column.size());
  }
  for (std::size_t r = 0; r < rows; ++r) {
    std::string line;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::string cell = r < columns[c].size() ? columns[c][r] : std::string();
      line += cell;
      if (c + 1 < columns.size()) line += std::string(widths[c] - display_width(cell) + 3, ' ');
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out << line << '\n';
  }
}

// One quiet run per K, printed as columns (map, blank line, summary). Ctrl-C stops the run
// in flight at its next step and the rest are not started: nothing is printed but one
// line, and the status is 130.
int compare_runs(const RunOptions &options, const std::vector<int> &ks, std::ostream &out) {
  std::vector<std::vector<std::string>> columns;
  int status = 0;
  double total_ms = 0.0;
  RunControls controls;
  controls.interrupted = &SigintGuard::interrupted;
  const SigintGuard sigint;
  for (const int k : ks) {
    RunOptions one = options;
    one.subcells = k;
    std::ostringstream text;
    const RunSummary summary = run_world(one, text, controls);
    if (summary.interrupted) {
      out << "compare: interrupted by Ctrl-C\n";
      return exit_status(summary);
    }
    status = std::max(status, exit_status(summary));
    // The wall time varies from run to run: one total line at the end keeps columns stable.
    std::vector<std::string> lines = split(text.str(), '\n');
    std::erase_if(lines, [](const std::string &l) { return l.starts_with("wall_time_ms: "); });
    total_ms += summary.wall_time_ms;
    columns.push_back(std::move(lines));
  }
  print_columns(columns, out);
  out << fmt::format("wall_time_ms: {:.0f}\n", total_ms);
  return status;
}

}  // namespace

void add_compare_command(CLI::App &cli, CommandContext &context) {
  auto parsed = std::make_shared<RunOptions>();
  auto subcells = std::make_shared<std::string>("3,5");
  CLI::App *compare = cli.add_subcommand(
      "compare", "run the same world at several resolutions; maps and summaries side by side");
  add_exploration_options(*compare, *parsed);
  compare->remove_option(compare->get_option("--subcells"));
  compare->add_option("--subcells", *subcells, "K1,K2,...: the resolutions to compare (default 3,5)");
  compare->callback([compare, parsed, subcells, &context] {
    const std::vector<int> ks = parse_ks(*subcells);
    RunOptions options = checked_run_options(*compare, *parsed, true);
    options.output.quiet = true;
    print_warnings(options_not_applying(*compare, options));
    context.status = compare_runs(options, ks, std::cout);
  });
}

}  // namespace app
