// maze_mapper demo 1d: the textbook 1-D log-odds exercise (see mapping/demo_1d.hpp for the
// model and its conventions, render/demo_1d_render.hpp for the table and plots).

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "common/parse_number.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/demo_commands.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/random.hpp"
#include "mapping/demo_1d.hpp"
#include "app/cli/cli_options.hpp"
#include "app/cli/model_options.hpp"
#include "render/demo_1d_render.hpp"
#include "render/text_format.hpp"

namespace app {
namespace {

// demo 1d's options as typed.
struct Demo1dInput {
  std::string measurements;  // comma-separated cm
  bool measurements_given = false;  // otherwise the exercise's list
  mapping::Demo1dOptions options;   // resolution, length, behind, the sensor model (measurements set below)
  std::string order = "given";
  std::uint64_t seed = common::kDefaultSeed;
  std::string svg_path;
};

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

double parse_measurement(std::string_view item, std::size_t number) {
  const std::optional<double> value = common::parse_real(item);  // finite: checked with the others
  if (!value) {
    throw common::InputError(
        fmt::format("--measurements item {} is not a number (got '{}')", number, item));
  }
  return *value;
}

// "101, 82,91" -> {101, 82, 91}; an empty or blank text is an empty list.
std::vector<double> parse_measurements(std::string_view text) {
  std::vector<double> values;
  if (trimmed(text).empty()) return values;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    values.push_back(parse_measurement(trimmed(text.substr(start, comma - start)), values.size() + 1));
    if (comma == std::string_view::npos) return values;
    start = comma + 1;
  }
}

mapping::Demo1dOptions to_options(const Demo1dInput &input) {
  mapping::Demo1dOptions options = input.options;
  if (input.measurements_given) options.measurements_cm = parse_measurements(input.measurements);
  mapping::validate(options);
  if (input.order != "given" && input.order != "shuffle") {
    throw common::InputError("--order must be given or shuffle (got " + input.order + ")");
  }
  return options;
}

std::string joined(const std::vector<double> &values) {
  std::string out;
  for (const double v : values) out += (out.empty() ? "" : ", ") + render::short_number(v);
  return out;
}

std::string cells_summary(const std::vector<double> &positions) {
  const auto cm = [](double x) { return render::short_number(x); };
  if (positions.size() == 1) return "1 cell at 0 cm";
  if (positions.size() <= 3) return fmt::format("{} cells at {} cm", positions.size(), joined(positions));
  return fmt::format("{} cells at {}, {}, ..., {} cm", positions.size(), cm(positions[0]),
                     cm(positions[1]), cm(positions.back()));
}

// The set-up, with every number the table can be checked against by hand.
std::string header(const mapping::Demo1dOptions &options) {
  const mapping::SensorModel model(options.model);
  const std::vector<double> positions = mapping::cell_positions_cm(options);
  const auto p = [](double v) { return render::short_number(v); };
  const auto l4 = [](double v) { return render::fixed(v, 4); };
  const std::string behind = "z + " + p(options.behind_cm);
  std::string out = "1-D log-odds exercise: " + cells_summary(positions) + "\n";
  out += fmt::format("robot at 0 cm looking toward {} cm\n", p(positions.back()));
  out += "inverse model for a cell at x and a measurement z (cm):\n";
  out += fmt::format("  {:<{}}  free      p = {}  l(p) = {:>7}\n", "x < z", behind.size() + 10,
                     p(options.model.p_free), l4(mapping::log_odds(options.model.p_free, options.model.base)));
  out += fmt::format("  {:<{}}  occupied  p = {}  l(p) = {:>7}\n", "z <= x <= " + behind,
                     behind.size() + 10, p(options.model.p_occ),
                     l4(mapping::log_odds(options.model.p_occ, options.model.base)));
  out += fmt::format("  {:<{}}  no update\n", "x > " + behind, behind.size() + 10);
  out += fmt::format("prior {} (l0 = {}), log base {}; update l <- l + l(inv(z)) - l0\n",
                     p(options.model.prior), l4(model.prior_log_odds()),
                     mapping::to_string(options.model.base));
  out += fmt::format("by hand: log-odds = l0 + free * ({}) + occupied * ({})\n",
                     l4(model.free_increment()), l4(model.occupied_increment()));
  return out;
}

std::string order_report(const std::vector<mapping::Demo1dCell> &given,
                         const std::vector<mapping::Demo1dCell> &shuffled_result) {
  const double difference = mapping::max_log_odds_difference(given, shuffled_result);
  const std::string shown = difference == 0.0 ? "0" : fmt::format("{:.1e}", difference);
  const bool same = difference <= mapping::kOrderTolerance;
  return fmt::format("order independence: {} the given order's result (largest log-odds "
                     "difference {}, tolerance {:.0e})\n",
                     same ? "same as" : "NOT the same as", shown, mapping::kOrderTolerance);
}

int run_demo_1d(const Demo1dInput &input) {
  const mapping::Demo1dOptions options = to_options(input);
  const std::uint64_t seed = input.seed;
  const bool shuffle = input.order == "shuffle";
  const std::vector<double> order =
      shuffle ? mapping::shuffled(options.measurements_cm, seed) : options.measurements_cm;
  const std::vector<mapping::Demo1dCell> cells = mapping::integrate(options, order);
  const std::string title =
      fmt::format("1-D log-odds exercise: belief after {} measurements", order.size());
  if (!input.svg_path.empty()) {
    common::write_file_atomically(input.svg_path, render::svg_belief_plot(cells, title));
  }
  std::string out = header(options);
  out += "measurements (cm, in the order given): " + joined(options.measurements_cm) + "\n";
  if (shuffle) out += fmt::format("integrated in a shuffled order (seed {}): {}\n", seed, joined(order));
  out += "\n" + render::demo_1d_table(cells) + "\n" + render::ascii_belief_plot(cells);
  int status = 0;
  if (shuffle) {
    const auto given = mapping::integrate(options, options.measurements_cm);
    out += "\n" + order_report(given, cells);
    if (mapping::max_log_odds_difference(given, cells) > mapping::kOrderTolerance) status = 1;
  }
  if (!input.svg_path.empty()) out += "\nwrote " + input.svg_path + "\n";
  std::cout << out;
  return status;
}

// `demo` alone: the demos, one a line, as `robot` alone lists the robots.
void list_demos(const CLI::App &demo, std::ostream &out) {
  std::size_t width = 0;
  const auto all = [](const CLI::App *) { return true; };
  for (const CLI::App *d : demo.get_subcommands(all)) width = std::max(width, d->get_name().size());
  for (const CLI::App *d : demo.get_subcommands(all)) {
    out << fmt::format("{:<{}}  {}\n", d->get_name(), width, d->get_description());
  }
}

void add_demo_1d(CLI::App &demo, CommandContext &context) {
  CLI::App *one_d = demo.add_subcommand("1d", "the textbook 1-D log-odds exercise");
  auto input = std::make_shared<Demo1dInput>();
  mapping::Demo1dOptions &o = input->options;
  CLI::Option *measurements = one_d->add_option(
      "--measurements", input->measurements,
      fmt::format("comma-separated ranges in cm (default {})", fmt::join(o.measurements_cm, ",")));
  add_model_options(*one_d, o.model);
  one_d->add_option("--behind", o.behind_cm, fmt::format("occupied stretch behind a hit, cm (default {})", o.behind_cm));
  one_d->add_option("--resolution", o.resolution_cm, fmt::format("spacing of the cells, cm (default {})", o.resolution_cm));
  one_d->add_option("--length", o.length_cm, fmt::format("position of the last cell, cm (default {})", o.length_cm));
  one_d->add_option("--order", input->order, "integration order: given or shuffle (default given)");
  add_seed_option(*one_d, input->seed, "the shuffle");
  one_d->add_option("--svg", input->svg_path, "FILE: also write the plot as an SVG file");
  one_d->callback([&context, input, measurements] {
    input->measurements_given = measurements->count() > 0;
    context.status = run_demo_1d(*input);
  });
}

}  // namespace

void add_demo_command(CLI::App &cli, CommandContext &context) {
  CLI::App *demo = cli.add_subcommand("demo", "teaching demos of the log-odds mapping; alone, the list of demos");
  demo->require_subcommand(0, 1);
  add_demo_1d(*demo, context);
  add_demo_pie(*demo, context);
  add_demo_cone(*demo, context);
  demo->callback([demo, &context] {
    if (!demo->get_subcommands().empty()) return;
    list_demos(*demo, std::cout);
    context.status = 0;
  });
}

}  // namespace app
