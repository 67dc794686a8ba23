// maze_mapper compare [WORLD] --subcells K1,K2,... [options]: the same world at several
// resolutions: maps side by side under a heading per K, then the summaries as one table.

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "common/parse_number.hpp"
#include "common/csv.hpp"
#include "app/report/files_recorder.hpp"
#include "app/report/outputs.hpp"
#include "app/run/run.hpp"
#include "app/run/run_report.hpp"
#include "app/cli/run_cli.hpp"
#include "app/run/terminal.hpp"
#include "app/cli/commands.hpp"
#include "common/atomic_file.hpp"
#include "common/interrupt.hpp"
#include "common/error.hpp"

namespace app {
namespace {

// compare's own output options.
struct CompareOutput {
  bool quiet = false;     // the summary table only, no maps
  std::string out_dir;    // DIR/compare.csv and DIR/kK/
};

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

// "3,5" -> {3, 5}, each K checked: digits only (strtol took " 3" and "+3"), and whole as
// typed (4294967299 was cast to the int 3; a longer one is no K).
std::vector<int> parse_ks(const std::string &subcells) {
  std::vector<int> ks;
  // split() drops a trailing empty part: "3," would pass as "3".
  if (subcells.ends_with(',')) throw common::InputError(fmt::format("--subcells must be a list like 3,5 (got '{}')", subcells));
  for (const std::string &part : split(subcells, ',')) {
    const bool digits = !part.empty() && part.size() <= 9 &&
                        part.find_first_not_of("0123456789") == std::string::npos;
    if (!digits) throw common::InputError(fmt::format("--subcells must be a list like 3,5 (got '{}')", subcells));
    const int k = common::parse_number<int>(part).value_or(0);
    validate_subcells(k);
    if (std::find(ks.begin(), ks.end(), k) != ks.end()) {
      throw common::InputError(fmt::format("--subcells lists K {} twice (got '{}'); each K is one run", k, subcells));
    }
    ks.push_back(k);
  }
  if (ks.empty()) throw common::InputError("--subcells needs at least one K, a list like 3,5 (got '')");
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

// A run's summary lines as (key, value), wall_time_ms left out: it varies from run to run,
// and one total line at the end keeps the table stable.
using Summary = std::vector<std::pair<std::string, std::string>>;

Summary table_pairs(const Report &report) {
  Summary pairs = summary_pairs(report);
  std::erase_if(pairs, [](const auto &pair) { return pair.first == "wall_time_ms"; });
  return pairs;
}

// The summaries as a table: a key column, then a column per K under its heading. A key one
// run lacks (a plan that found no path) is blank in its column.
std::vector<std::vector<std::string>> summary_table(const std::vector<int> &ks, const std::vector<Summary> &summaries) {
  std::vector<std::string> keys;
  for (const Summary &s : summaries) {
    for (const auto &[key, value] : s) {
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    }
  }
  std::vector<std::vector<std::string>> columns{{""}};
  for (const std::string &key : keys) columns[0].push_back(key);
  for (std::size_t n = 0; n < ks.size(); ++n) {
    std::vector<std::string> column{fmt::format("K {}", ks[n])};
    for (const std::string &key : keys) {
      const auto it = std::find_if(summaries[n].begin(), summaries[n].end(), [&](const auto &p) { return p.first == key; });
      column.push_back(it == summaries[n].end() ? "" : it->second);
    }
    columns.push_back(std::move(column));
  }
  return columns;
}

// compare.csv: a row per K, the K first, then the summary's keys as the table prints them.
std::string compare_csv(const std::vector<int> &ks, const std::vector<std::vector<std::string>> &table) {
  std::string out = "k";
  for (std::size_t row = 1; row < table[0].size(); ++row) out += "," + table[0][row];
  out += "\n";
  for (std::size_t n = 0; n < ks.size(); ++n) {
    out += std::to_string(ks[n]);
    for (std::size_t row = 1; row < table[n + 1].size(); ++row) {
      out += ',';
      out += common::csv_field(table[n + 1][row]);
    }
    out += "\n";
  }
  return out;
}

// The names compare --out may write: compare.csv, and run --out's in each kK/.
std::vector<std::string> compare_output_names(const std::vector<int> &ks) {
  std::vector<std::string> names{"compare.csv"};
  for (const int k : ks) {
    for (const std::string &name : run_output_names()) names.push_back(fmt::format("k{}/{}", k, name));
  }
  return names;
}

// One quiet run per K: the maps side by side under a heading per K (unless --quiet), then
// the summaries as one table. With --out DIR each run writes run --out's files into DIR/kK/
// and DIR/compare.csv holds the table. Ctrl-C stops the run in flight at its next step and
// the rest are not started: nothing is printed but one line, and the status is 130.
int compare_runs(const RunOptions &options, const CompareOutput &output, const std::vector<int> &ks, std::ostream &out) {
  std::vector<std::vector<std::string>> maps;
  std::vector<Summary> summaries;
  int status = 0;
  double total_ms = 0.0;
  RunControls controls;
  controls.interrupted = &common::interrupted;
  std::exception_ptr no_space;  // a full disk: said after the table, which the user still gets
  controls.no_space = &no_space;
  const common::SignalsStopWork stop_signals;
  if (!output.out_dir.empty()) {
    prepare_output_dir(output.out_dir);
    refuse_outputs_over_inputs(output.out_dir, compare_output_names(ks), run_inputs(options));
  }
  for (const int k : ks) {
    RunOptions one = options;
    one.subcells = k;
    if (!output.out_dir.empty()) one.output.out_dir = (std::filesystem::path(output.out_dir) / fmt::format("k{}", k)).string();
    std::ostringstream text;
    const RunSummary summary = run_and_write(one, text, controls);
    if (summary.interrupted) {
      out << fmt::format("compare: interrupted by {}\n", common::interrupt_name());
      return exit_status(summary);
    }
    status = std::max(status, exit_status(summary));
    total_ms += summary.wall_time_ms;
    const Report report = run_report(one, summary);
    const std::string block = format_summary(report);
    if (!text.str().ends_with(block)) throw common::RuntimeFailure("compare: a run's output does not end in its summary");
    const std::string map = text.str().substr(0, text.str().size() - block.size());
    maps.push_back(split(fmt::format("K {}\n", k) + map, '\n'));
    summaries.push_back(table_pairs(report));
  }
  const auto table = summary_table(ks, summaries);
  if (!output.quiet) print_columns(maps, out);
  print_columns(table, out);
  if (!output.quiet) out << fmt::format("wall_time_ms: {:.0f}\n", total_ms);  // --quiet: the table alone
  if (!output.out_dir.empty() && !no_space) {
    const std::filesystem::path dir(output.out_dir);
    try {
      common::write_file_atomically((dir / "compare.csv").string(), compare_csv(ks, table));
      std::string wrote = "wrote " + (dir / "compare.csv").string();
      for (const int k : ks) wrote += ", " + (dir / fmt::format("k{}", k) / "").string();
      out << wrote << '\n';
    } catch (const common::NoSpaceError &) {
      no_space = std::current_exception();
    }
  }
  if (no_space) {
    out << std::flush;
    std::rethrow_exception(no_space);
  }
  return status;
}

}  // namespace

void add_compare_command(CLI::App &cli, CommandContext &context) {
  auto parsed = std::make_shared<RunOptions>();
  auto subcells = std::make_shared<std::string>("3,5");
  auto output = std::make_shared<CompareOutput>();
  CLI::App *compare = cli.add_subcommand(
      "compare", "run the same world at several resolutions; maps and summaries side by side");
  add_exploration_options(*compare, *parsed);
  compare->remove_option(compare->get_option("--subcells"));
  compare->add_option("--subcells", *subcells, "K1,K2,...: the resolutions to compare (default 3,5)");
  compare->add_flag("--quiet", output->quiet, "print only the summaries' table, not the maps");
  compare->add_option("-o,--out", output->out_dir,
                      "DIR: compare.csv (a row per K) and run --out's files for each K in DIR/kK/ (trace.csv left out)");
  compare->callback([compare, parsed, subcells, output, &context] {
    const std::vector<int> ks = parse_ks(*subcells);
    RunOptions options = checked_run_options(*compare, *parsed, true);
    options.output.quiet = true;
    options.output.trace = false;
    print_warnings(options_not_applying(*compare, options));
    context.status = compare_runs(options, *output, ks, std::cout);
  });
}

}  // namespace app
