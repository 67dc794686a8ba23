#include "app/course/demo_trilaterate.hpp"

#include <array>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "app/run/localization.hpp"
#include "app/run/option_values.hpp"
#include "common/error.hpp"
#include "common/random.hpp"

namespace app::course {
namespace {

using loc::kArenaLandmarks;
using Distances = std::array<std::optional<double>, 4>;

std::string trimmed(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return std::string(s);
}

// "3.2,4.1,2.9" or "3.2,-,2.9,3.7": yellow, red, green[, blue]; "-" not measured.
Distances parse_distances(const std::string &text) {
  std::vector<std::string> items;
  std::size_t from = 0;
  for (std::size_t comma = text.find(','); ; comma = text.find(',', from)) {
    items.push_back(trimmed(std::string_view(text).substr(from, comma == std::string::npos ? comma : comma - from)));
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  common::require_input(items.size() == 3 || items.size() == 4,
                  fmt::format("--distances needs 3 or 4 numbers, yellow,red,green[,blue] (got {})", items.size()));
  std::string numbers;
  int missing = 0;
  for (const std::string &item : items) {
    missing += item == "-";
    numbers += (numbers.empty() ? "" : ",") + (item == "-" ? std::string("0") : item);
  }
  common::require_input(missing == 0 || (items.size() == 4 && missing == 1),
                  "--distances may leave out one landmark (-) only in a list of four");
  const std::vector<double> values = parse_number_list(numbers, "--distances");
  Distances d;
  for (std::size_t k = 0; k < items.size(); ++k) {
    if (items[k] == "-") continue;
    common::require_input(std::isfinite(values[k]) && values[k] >= 0.0,
                    fmt::format("--distances must be finite numbers >= 0 m (got {})", items[k]));
    d[k] = values[k];
  }
  return d;
}

struct Measured {
  Distances distances;
  std::optional<std::array<double, 2>> pose;
  std::string how;
};

Measured measure(const DemoTrilaterateInput &in) {
  common::require_input(in.distances.empty() || in.pose.empty(), "--distances and --pose are two inputs: give one");
  common::require_input(!in.noise_m || !in.pose.empty(), "--noise applies with --pose (the distances are given)");
  common::require_input(!in.seed || in.noise_m, "--seed applies with --noise (exact distances draw nothing)");
  common::require_input(std::isfinite(in.sigma_m) && in.sigma_m > 0.0, fmt::format("--sigma must be > 0 m (got {:g})", in.sigma_m));
  if (in.pose.empty()) {
    const std::string text = in.distances.empty() ? kDefaultDistances : in.distances;
    return {parse_distances(text), std::nullopt, in.distances.empty() ? "the default distances" : "--distances"};
  }
  const std::vector<double> p = parse_number_list(in.pose, "--pose", 2);
  common::require_input(std::abs(p[0]) <= loc::kArenaHalf_m && std::abs(p[1]) <= loc::kArenaHalf_m,
                  fmt::format("--pose must be inside the arena, x and y in [-2.5, 2.5] m (got {})", in.pose));
  Measured m{{}, std::array<double, 2>{p[0], p[1]}, "computed from --pose"};
  if (in.noise_m) {
    common::require_input(std::isfinite(*in.noise_m) && *in.noise_m >= 0.0,
                    fmt::format("--noise must be >= 0 m (got {:g})", *in.noise_m));
    m.how += fmt::format(", plus Gaussian noise sigma {:g} m (seed {})", *in.noise_m, in.seed.value_or(1));
  }
  common::Rng rng(in.seed.value_or(1));
  for (std::size_t k = 0; k < 4; ++k) {
    double d = std::hypot(p[0] - kArenaLandmarks[k].x_m, p[1] - kArenaLandmarks[k].y_m);
    if (in.noise_m) d = std::max(0.0, d + rng.normal(0.0, *in.noise_m));
    m.distances[k] = d;
  }
  return m;
}

std::string landmark_table(const Measured &m) {
  std::string out = "landmark  number    x_m    y_m  distance_m\n";
  for (std::size_t k = 0; k < 4; ++k) {
    const auto &l = kArenaLandmarks[k];
    out += fmt::format("{:<8}  {:>6}  {:>5.2f}  {:>5.2f}  {}\n", l.name, k + 1, l.x_m, l.y_m,
                       m.distances[k] ? fmt::format("{:.4f}", *m.distances[k]) : "- (not measured)");
  }
  return out;
}

std::string cell_words(double x, double y) {
  const std::optional<int> cell = loc::arena_cell(x, y);
  return cell ? fmt::format("cell {}", *cell) : "outside the arena";
}

std::string closed_form(const Measured &m) {
  std::array<loc::Landmark, 3> marks{};
  std::array<double, 3> r{};
  std::array<std::size_t, 3> used{};
  std::size_t n = 0;
  for (std::size_t k = 0; k < 4 && n < 3; ++k) {
    if (m.distances[k]) used[n] = k, marks[n] = kArenaLandmarks[k], r[n++] = *m.distances[k];
  }
  const loc::Trilateration t = loc::trilaterate(marks, r);
  std::string out = fmt::format("closed form with {} (1), {} (2) and {} (3): circle 1 minus circle 2, circle 2 minus circle 3\n",
                                marks[0].name, marks[1].name, marks[2].name);
  out += fmt::format("  A = 2 (x2 - x1) = {:.4f}   B = 2 (y2 - y1) = {:.4f}\n", t.a, t.b);
  out += fmt::format("  C = r1^2 - r2^2 - x1^2 + x2^2 - y1^2 + y2^2 = {:.4f}\n", t.c);
  out += fmt::format("  D = 2 (x3 - x2) = {:.4f}   E = 2 (y3 - y2) = {:.4f}\n", t.d, t.e);
  out += fmt::format("  F = r2^2 - r3^2 - x2^2 + x3^2 - y2^2 + y3^2 = {:.4f}\n", t.f);
  out += fmt::format("  x = (C E - F B) / (E A - B D) = {:.4f} / {:.4f} = {:.6f} m\n", t.c * t.e - t.f * t.b,
                     t.e * t.a - t.b * t.d, t.x_m);
  out += fmt::format("  y = (C D - A F) / (B D - A E) = {:.4f} / {:.4f} = {:.6f} m\n", t.c * t.d - t.a * t.f,
                     t.b * t.d - t.a * t.e, t.y_m);
  out += fmt::format("  (x, y) = ({:.4f}, {:.4f}) m: {}\n", t.x_m, t.y_m, cell_words(t.x_m, t.y_m));
  for (std::size_t k = 0; k < 4; ++k) {
    if (!m.distances[k] || k == used[0] || k == used[1] || k == used[2]) continue;
    const double from = std::hypot(t.x_m - kArenaLandmarks[k].x_m, t.y_m - kArenaLandmarks[k].y_m);
    out += fmt::format("  {} is not used by the closed form: measured {:.4f} m, from (x, y) {:.4f} m, residual {:+.4f} m\n",
                       kArenaLandmarks[k].name, *m.distances[k], from, *m.distances[k] - from);
  }
  if (m.pose) {
    out += fmt::format("  the true pose ({:.4f}, {:.4f}) m is {:.4f} m away\n", (*m.pose)[0], (*m.pose)[1],
                       std::hypot(t.x_m - (*m.pose)[0], t.y_m - (*m.pose)[1]));
  }
  return out;
}

std::string score_grid(const Measured &m, double sigma) {
  const std::vector<double> s = loc::cell_scores(m.distances, sigma);
  std::string out = fmt::format("probabilistic: each cell's score is the product over the measured landmarks of\n"
                                "N(measured distance; the cell centre's distance to the landmark, sigma {:g} m), "
                                "normalised; north row first (cells 1 to 5):\n", sigma);
  std::size_t best = 0;
  for (std::size_t n = 0; n < s.size(); ++n) {
    if (s[n] > s[best]) best = n;
    out += fmt::format("{}{:.3f}{}", n % 5 == 0 ? "  " : " ", s[n], n % 5 == 4 ? "\n" : "");
  }
  out += fmt::format("most likely: cell {} ({:.3f})\n", best + 1, s[best]);
  return out;
}

}  // namespace

std::string run_demo_trilaterate(const DemoTrilaterateInput &input) {
  const Measured m = measure(input);
  std::string out = "trilateration in the 5 x 5 m arena: 25 cells of 1 m numbered row by row from the north-west\n"
                    "(cell 1 is x in [-2.5, -1.5], y in [1.5, 2.5]); x east, y north, origin at the centre\n";
  if (m.pose) {
    out += fmt::format("true pose ({:.4f}, {:.4f}) m: {}\n", (*m.pose)[0], (*m.pose)[1], cell_words((*m.pose)[0], (*m.pose)[1]));
  }
  out += "distances: " + m.how + "\n\n" + landmark_table(m) + "\n" + closed_form(m) + "\n" + score_grid(m, input.sigma_m);
  return out;
}

}  // namespace app::course
