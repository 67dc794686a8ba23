#include "app/course/demo_1d_exercise.hpp"

#include <optional>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "app/course/demo_1d_render.hpp"
#include "app/run/option_values.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/parse_number.hpp"
#include "mapping/log_odds.hpp"
#include "render/text_format.hpp"

namespace app::course {
namespace {

// "101, 82,91" -> {101, 82, 91}; an empty or blank text is an empty list (which validate() refuses).
std::vector<double> parse_measurements(std::string_view text) {
  if (common::trim_blanks(text).empty()) return {};
  return parse_number_list(text, "--measurements");
}

Demo1dOptions demo_1d_options(const Demo1dInput &input) {
  Demo1dOptions options = input.options;
  if (input.measurements_given) options.measurements_cm = parse_measurements(input.measurements);
  validate(options);
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
std::string demo_1d_header(const Demo1dOptions &options) {
  const mapping::SensorModel model(options.model);
  const std::vector<double> positions = cell_positions_cm(options);
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

std::string order_report(const std::vector<Demo1dCell> &given,
                         const std::vector<Demo1dCell> &shuffled_result) {
  const double difference = max_log_odds_difference(given, shuffled_result);
  const std::string shown = difference == 0.0 ? "0" : fmt::format("{:.1e}", difference);
  const bool same = difference <= kOrderTolerance;
  return fmt::format("order independence: {} the given order's result (largest log-odds "
                     "difference {}, tolerance {:.0e})\n",
                     same ? "same as" : "NOT the same as", shown, kOrderTolerance);
}

}  // namespace

Demo1dOutput run_demo_1d(const Demo1dInput &input) {
  const Demo1dOptions options = demo_1d_options(input);
  const std::uint64_t seed = input.seed;
  const bool shuffle = input.order == "shuffle";
  const std::vector<double> order =
      shuffle ? shuffled(options.measurements_cm, seed) : options.measurements_cm;
  const std::vector<Demo1dCell> cells = integrate(options, order);
  const std::string title =
      fmt::format("1-D log-odds exercise: belief after {} measurements", order.size());
  if (!input.svg_path.empty()) {
    common::write_file_atomically(input.svg_path, svg_belief_plot(cells, title));
  }
  std::string out = demo_1d_header(options);
  out += "measurements (cm, in the order given): " + joined(options.measurements_cm) + "\n";
  if (shuffle) out += fmt::format("integrated in a shuffled order (seed {}): {}\n", seed, joined(order));
  out += "\n" + demo_1d_table(cells) + "\n" + ascii_belief_plot(cells);
  int status = 0;
  if (shuffle) {
    const auto given = integrate(options, options.measurements_cm);
    out += "\n" + order_report(given, cells);
    if (max_log_odds_difference(given, cells) > kOrderTolerance) status = 1;
  }
  if (!input.svg_path.empty()) out += "\nwrote " + input.svg_path + "\n";
  return {out, status};
}

}  // namespace app::course
