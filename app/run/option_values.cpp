#include "app/run/option_values.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "common/error.hpp"
#include "common/parse_number.hpp"

namespace app {

namespace {

// "a, b ,c" -> {"a", "b", "c"}, each trimmed.
std::vector<std::string_view> comma_items(std::string_view text) {
  std::vector<std::string_view> items;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    items.push_back(common::trim_blanks(text.substr(start, comma == std::string_view::npos ? text.npos : comma - start)));
    if (comma == std::string_view::npos) return items;
    start = comma + 1;
  }
}

[[noreturn]] void throw_not_a_number(const std::string &option, std::size_t item, std::string_view text) {
  throw common::InputError(fmt::format("{} item {} is not a number (got '{}'{})", option, item, text,
                                       common::range_note<double>(text)));
}

}  // namespace

std::vector<double> parse_number_list(std::string_view text, const std::string &option, std::size_t count) {
  std::vector<double> values;
  for (const std::string_view item : comma_items(text)) {
    const std::optional<double> value = common::parse_real(item);  // finite: checked by each option
    if (!value) throw_not_a_number(option, values.size() + 1, item);
    values.push_back(*value);
  }
  if (count > 0 && values.size() != count) {
    throw common::InputError(fmt::format("{} needs {} numbers (got {})", option, count, values.size()));
  }
  return values;
}

std::optional<Length> length_of(std::string_view text) {
  Length length;
  if (text.ends_with("cm")) {
    length.unit = LengthUnit::cm;
    text.remove_suffix(2);
  } else if (text.ends_with("m")) {
    length.unit = LengthUnit::m;
    text.remove_suffix(1);
  }
  const std::optional<double> value = common::parse_real(text);
  if (!value) return std::nullopt;
  length.value = *value;
  return length;
}

double metres(const Length &length, LengthUnit bare) {
  const LengthUnit unit = length.unit == LengthUnit::none ? bare : length.unit;
  return unit == LengthUnit::cm ? length.value / 100.0 : length.value;
}

double centimetres(const Length &length, LengthUnit bare) {
  const LengthUnit unit = length.unit == LengthUnit::none ? bare : length.unit;
  return unit == LengthUnit::cm ? length.value : length.value * 100.0;
}

namespace {

// YAW: degrees, with or without the unit deg; radians with rad; or a heading letter.
void read_yaw(std::string_view text, const std::string &option, PoseArgument &pose) {
  constexpr std::pair<std::string_view, double> kHeadings[] = {{"E", 0.0}, {"N", 90.0}, {"W", 180.0}, {"S", 270.0}};
  for (const auto &[letter, degrees] : kHeadings) {
    if (text == letter) {
      pose.yaw_deg = degrees;
      pose.yaw_rad = degrees * std::numbers::pi / 180.0;
      return;
    }
  }
  const bool radians = text.ends_with("rad");
  if (radians || text.ends_with("deg")) text.remove_suffix(3);
  const std::optional<double> value = common::parse_real(text);
  if (!value) throw_not_a_number(option, 3, text);
  pose.yaw_deg = radians ? *value * 180.0 / std::numbers::pi : *value;
  pose.yaw_rad = radians ? *value : *value * std::numbers::pi / 180.0;
}

}  // namespace

PoseArgument parse_pose(const std::string &text, const std::string &option, std::vector<std::string> &warnings,
                        PoseYaw yaw) {
  const std::vector<std::string_view> items = comma_items(text);
  const bool count_ok = items.size() == 3 || (yaw == PoseYaw::optional && items.size() == 2);
  if (!count_ok) {
    throw common::InputError(fmt::format("{} needs {} numbers (got {})", option,
                                         yaw == PoseYaw::optional ? "2 or 3" : "3", items.size()));
  }
  std::optional<Length> place[2];
  for (std::size_t k = 0; k < 2; ++k) {
    place[k] = length_of(items[k]);
    if (!place[k]) throw_not_a_number(option, k + 1, items[k]);
  }
  PoseArgument pose{metres(*place[0]), metres(*place[1]), 0.0, 0.0, items.size() == 3};
  if (pose.yaw_given) read_yaw(items[2], option, pose);
  if (!std::isfinite(pose.x_m) || !std::isfinite(pose.y_m) || !std::isfinite(pose.yaw_rad)) {
    throw common::InputError(fmt::format("{} must be {}finite numbers", option, items.size() == 3 ? "three " : ""));
  }
  // X and Y as they read with their unit, for the warnings' advice.
  const auto with_unit = [](std::string_view item, const Length &l) {
    return l.unit == LengthUnit::none ? std::string(item) + "m" : std::string(item);
  };
  const std::string place_text = with_unit(items[0], *place[0]) + "," + with_unit(items[1], *place[1]);
  if (place[0]->unit == LengthUnit::none || place[1]->unit == LengthUnit::none) {
    std::string advice = fmt::format("{} {}", option, place_text);
    if (pose.yaw_given) advice += fmt::format(",{}", items[2]);
    warnings.push_back(old_spelling_warning(fmt::format("{} {}", option, text), advice));
  }
  if (pose.yaw_given && items[2].ends_with("rad") && std::abs(pose.yaw_rad) > 2.0 * std::numbers::pi) {
    const std::string number(items[2].substr(0, items[2].size() - 3));
    warnings.push_back(fmt::format("warning: {} YAW {}rad is {:g} degrees, more than a turn; for {} degrees write {} {},{}",
                                   option, number, pose.yaw_deg, number, option, place_text, number));
  }
  return pose;
}

std::string old_spelling_warning(const std::string &old_spelling, const std::string &new_spelling) {
  return fmt::format("warning: {} is the old spelling; write {} (the old one goes in the next release)", old_spelling,
                     new_spelling);
}

}  // namespace app
