#include "app/course/explain.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "mapping/log_odds.hpp"
#include "render/text_format.hpp"

namespace app::course {
namespace {

using mapping::LogBase;

struct ProbabilityUse {
  double p;
  std::string use;
};

// The probabilities worth showing: this model's own, the classroom ones and those the seed
// set-ups use (docs/models.md: pie model logit(0.4) / logit(0.7); course reports' 0.99999).
std::vector<ProbabilityUse> probabilities_in_use(const mapping::SensorModelOptions &o) {
  std::vector<ProbabilityUse> uses{
      {o.p_free, "--p-free"},
      {o.prior, "--prior"},
      {o.p_occ, "--p-occ"},
      {0.3, "classroom free"},
      {0.5, "classroom prior"},
      {0.6, "classroom occupied"},
      {0.4, "pie model free"},
      {0.7, "pie model occupied"},
      {0.99999, "near-certain hit (course reports: 5.000 in base 10)"},
  };
  std::stable_sort(uses.begin(), uses.end(),
                   [](const ProbabilityUse &a, const ProbabilityUse &b) { return a.p < b.p; });
  std::vector<ProbabilityUse> merged;
  for (const ProbabilityUse &u : uses) {
    if (!merged.empty() && merged.back().p == u.p) {
      merged.back().use += "; " + u.use;
    } else {
      merged.push_back(u);
    }
  }
  return merged;
}

std::string four_decimals(double value) { return render::fixed(value, 4); }

std::string explain_header(const mapping::SensorModelOptions &o) {
  const std::string clamp =
      o.clamp ? fmt::format("clamp [{}, {}]", o.clamp->min, o.clamp->max) : "no clamp";
  std::string out = "explain: the inverse sensor model's numbers\n";
  out += "  l(p) = log_b(p / (1 - p))   p(l) = 1 - 1 / (1 + b^l)\n";
  out += "  update: l <- l + l(inv(z)) - l(prior), l(inv(z)) = l(p_free) or l(p_occ)\n";
  out += fmt::format("model: p_free {}, p_occ {}, prior {}, log base {}, {}\n", o.p_free, o.p_occ,
                     o.prior, mapping::to_string(o.base), clamp);
  return out;
}

std::string probability_table(const mapping::SensorModelOptions &o) {
  std::string out = fmt::format("{:<9}  {:>10}  {:>11}  {}\n", "p", "l (base e)", "l (base 10)",
                                "used as");
  for (const ProbabilityUse &u : probabilities_in_use(o)) {
    out += fmt::format("{:<9}  {:>10}  {:>11}  {}\n", u.p, four_decimals(mapping::log_odds(u.p, LogBase::e)),
                       four_decimals(mapping::log_odds(u.p, LogBase::ten)), u.use);
  }
  return out;
}

std::string increments(const mapping::SensorModel &model) {
  const mapping::SensorModelOptions &o = model.options();
  std::string out = fmt::format("increments in base {} (added to a cell's log-odds per update):\n",
                                mapping::to_string(o.base));
  out += fmt::format("  free      l({}) - l({}) = {:>8}\n", o.p_free, o.prior, four_decimals(model.free_increment()));
  out += fmt::format("  occupied  l({}) - l({}) = {:>8}\n", o.p_occ, o.prior, four_decimals(model.occupied_increment()));
  return out;
}

// Beliefs after 0 ... 3 repeated updates of one kind; `model` decides the clamp.
std::string repeated_updates(const mapping::SensorModel &model) {
  std::string out = fmt::format("{:>9}  {:>8}  {:>6}  {:>11}  {:>6}\n", "updates", "free: l",
                                "p", "occupied: l", "p");
  double free = model.prior_log_odds();
  double occupied = model.prior_log_odds();
  for (int n = 0; n <= 3; ++n) {
    out += fmt::format("{:>9}  {:>8}  {:>6}  {:>11}  {:>6}\n", n, four_decimals(free),
                       four_decimals(model.probability_of(free)), four_decimals(occupied),
                       four_decimals(model.probability_of(occupied)));
    free = model.update_free(free);
    occupied = model.update_occupied(occupied);
  }
  return out;
}

std::string repeated_section(const mapping::SensorModel &model) {
  const mapping::SensorModelOptions &o = model.options();
  mapping::SensorModelOptions unclamped = o;
  unclamped.clamp.reset();
  std::string out = fmt::format("repeated updates from the prior (l0 = {}), base {}:\n",
                                four_decimals(model.prior_log_odds()), mapping::to_string(o.base));
  out += repeated_updates(mapping::SensorModel(unclamped));
  if (o.clamp) {
    out += fmt::format("\nthe same with --clamp {} {} (each sum is held within the bounds):\n",
                       o.clamp->min, o.clamp->max);
    const std::string clamped = repeated_updates(model);
    out += clamped;
    if (clamped == repeated_updates(mapping::SensorModel(unclamped))) {
      out += "(the bounds are not reached within 3 updates)\n";
    }
  }
  return out;
}

}  // namespace

std::string explain_text(const mapping::SensorModelOptions &options) {
  const mapping::SensorModel model(options);
  const mapping::SensorModelOptions &o = model.options();
  return explain_header(o) + "\n" + probability_table(o) + "\n" + increments(model) + "\n" + repeated_section(model);
}

}  // namespace app::course
