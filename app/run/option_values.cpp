#include "app/run/option_values.hpp"

#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "common/error.hpp"
#include "common/parse_number.hpp"

namespace app {

std::vector<double> parse_number_list(std::string_view text, const std::string &option, std::size_t count) {
  std::vector<double> values;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    std::string_view item = text.substr(start, comma == std::string_view::npos ? text.npos : comma - start);
    item = common::trim_blanks(item);
    const std::optional<double> value = common::parse_real(item);  // finite: checked by each option
    if (!value) {
      throw common::InputError(fmt::format("{} item {} is not a number (got '{}'{})", option, values.size() + 1, item,
                                           common::range_note<double>(item)));
    }
    values.push_back(*value);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (count > 0 && values.size() != count) {
    throw common::InputError(fmt::format("{} needs {} numbers (got {})", option, count, values.size()));
  }
  return values;
}

PoseArgument parse_pose(const std::string &text, const std::string &option, std::vector<std::string> &warnings) {
  std::string numbers = text;
  bool radians = false;
  if (numbers.ends_with("rad")) {
    radians = true;
    numbers.resize(numbers.size() - 3);
  } else if (numbers.ends_with("deg")) {
    numbers.resize(numbers.size() - 3);
  }
  const std::vector<double> values = parse_number_list(numbers, option, 3);
  for (const double v : values) {
    if (!std::isfinite(v)) throw common::InputError(fmt::format("{} must be three finite numbers", option));
  }
  PoseArgument pose{values[0], values[1], values[2], values[2]};
  if (radians) {
    pose.yaw_deg = values[2] * 180.0 / std::numbers::pi;
    if (std::abs(values[2]) > 2.0 * std::numbers::pi) {
      warnings.push_back(fmt::format("warning: {} YAW {}rad is {:g} degrees, more than a turn; for {} degrees write {} "
                                     "{:g},{:g},{}",
                                     option, values[2], pose.yaw_deg, values[2], option, values[0], values[1], values[2]));
    }
  } else {
    pose.yaw_rad = values[2] * std::numbers::pi / 180.0;
  }
  return pose;
}

}  // namespace app
