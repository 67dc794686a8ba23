#include "common/parse_number.hpp"
#include "app/mms/mms_protocol.hpp"

#include <array>
#include <limits>
#include <vector>

#include <fmt/format.h>

namespace app {
namespace {

struct Word {
  std::string_view name;
  MmsVerb verb;
  bool takes_count;  // an optional second token: N
};

// The commands that answer, with their optional count (mms's executeCommand).
constexpr std::array kAnswered{
    Word{"mazeWidth", MmsVerb::maze_width, false},       Word{"mazeHeight", MmsVerb::maze_height, false},
    Word{"wallFront", MmsVerb::wall_front, true},        Word{"wallRight", MmsVerb::wall_right, true},
    Word{"wallLeft", MmsVerb::wall_left, true},          Word{"wallBack", MmsVerb::wall_back, true},
    Word{"wallFrontLeft", MmsVerb::wall_front_left, true}, Word{"wallFrontRight", MmsVerb::wall_front_right, true},
    Word{"wallBackLeft", MmsVerb::wall_back_left, true}, Word{"wallBackRight", MmsVerb::wall_back_right, true},
    Word{"moveForward", MmsVerb::move_forward, true},    Word{"moveForwardHalf", MmsVerb::move_forward_half, true},
    Word{"turnRight", MmsVerb::turn_right, false},       Word{"turnRight90", MmsVerb::turn_right, false},
    Word{"turnLeft", MmsVerb::turn_left, false},         Word{"turnLeft90", MmsVerb::turn_left, false},
    Word{"turnRight45", MmsVerb::turn_right_45, false},  Word{"turnLeft45", MmsVerb::turn_left_45, false},
    Word{"wasReset", MmsVerb::was_reset, false},         Word{"ackReset", MmsVerb::ack_reset, false},
    Word{"getStat", MmsVerb::get_stat, true},
};

struct Color {
  char letter;
  std::string_view name;
  MmsRgb rgb;  // as mms draws it
};

constexpr std::array<Color, 17> kColors{{
    {'k', "black", {0, 0, 0}},          {'b', "blue", {0, 0, 179}},         {'a', "gray", {179, 179, 179}},
    {'c', "cyan", {0, 102, 102}},       {'g', "green", {0, 179, 0}},        {'o', "orange", {179, 102, 0}},
    {'r', "red", {204, 0, 0}},          {'w', "white", {255, 255, 255}},    {'y', "yellow", {179, 179, 0}},
    {'B', "dark blue", {0, 0, 51}},     {'C', "dark cyan", {0, 51, 51}},    {'A', "dark gray", {26, 26, 26}},
    {'G', "dark green", {0, 77, 0}},    {'O', "dark orange", {51, 26, 0}},  {'R', "dark red", {77, 0, 0}},
    {'V', "dark violet", {51, 0, 51}},  {'Y', "dark yellow", {51, 51, 0}},
}};

constexpr std::size_t kMaxTextChars = 10;

std::vector<std::string_view> tokens_of(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    if (line[i] == ' ') {
      ++i;
      continue;
    }
    const std::size_t end = line.find(' ', i);
    const std::size_t stop = end == std::string_view::npos ? line.size() : end;
    tokens.push_back(line.substr(i, stop - i));
    i = stop;
  }
  return tokens;
}

// A decimal integer with an optional sign, the whole token.
std::optional<int> integer(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  return common::parse_number<int>(token);
}

ParsedLine failed(std::string error) { return ParsedLine{std::nullopt, std::move(error)}; }

ParsedLine parse_cell_command(MmsVerb verb, std::string_view name, const std::vector<std::string_view> &tokens,
                              std::size_t arity, std::string_view usage) {
  const auto x = tokens.size() > 1 ? integer(tokens[1]) : std::nullopt;
  const auto y = tokens.size() > 2 ? integer(tokens[2]) : std::nullopt;
  if (tokens.size() != arity || !x || !y) return failed(fmt::format("{} takes {}", name, usage));
  MmsCommand c;
  c.verb = verb;
  c.x = *x;
  c.y = *y;
  return ParsedLine{c, {}};
}

ParsedLine parse_wall(MmsVerb verb, std::string_view name, const std::vector<std::string_view> &tokens) {
  ParsedLine parsed = parse_cell_command(verb, name, tokens, 4, "X Y D (D one of n e s w)");
  if (!parsed.command) return parsed;
  const std::string_view d = tokens[3];
  constexpr std::string_view kSides = "nesw";
  if (d.size() != 1 || kSides.find(static_cast<char>(d[0] | 0x20)) == std::string_view::npos) {
    return failed(fmt::format("{} takes X Y D (D one of n e s w)", name));
  }
  parsed.command->side = static_cast<char>(d[0] | 0x20);
  return parsed;
}

ParsedLine parse_set_color(const std::vector<std::string_view> &tokens) {
  ParsedLine parsed = parse_cell_command(MmsVerb::set_color, "setColor", tokens, 4, "X Y C (C a colour letter)");
  if (!parsed.command) return parsed;
  if (tokens[3].size() != 1 || !mms_color_name(tokens[3][0])) {
    return failed(fmt::format("setColor: '{}' is no colour (kbacgorwyBCAGORVY)", tokens[3]));
  }
  parsed.command->color = tokens[3][0];
  return parsed;
}

// setText X Y TEXT: single blanks separate X, Y and the text, which may hold blanks.
ParsedLine parse_set_text(std::string_view line) {
  std::string_view rest = line.substr(line.find(' ') + 1);
  const std::size_t after_x = rest.find(' ');
  const auto x = integer(rest.substr(0, after_x));
  rest = after_x == std::string_view::npos ? std::string_view{} : rest.substr(after_x + 1);
  const std::size_t after_y = rest.find(' ');
  const auto y = integer(rest.substr(0, after_y));
  if (!x || !y) return failed("setText takes X Y TEXT");
  MmsCommand c;
  c.verb = MmsVerb::set_text;
  c.x = *x;
  c.y = *y;
  const std::string_view text = after_y == std::string_view::npos ? std::string_view{} : rest.substr(after_y + 1);
  for (const char ch : text.substr(0, kMaxTextChars)) c.text += (ch >= 32 && ch < 127) ? ch : '?';
  return ParsedLine{c, {}};
}

ParsedLine parse_answered(const std::vector<std::string_view> &tokens) {
  for (const Word &w : kAnswered) {
    if (tokens[0] != w.name) continue;
    if (tokens.size() > 2 || (tokens.size() == 2 && !w.takes_count)) {
      return failed(fmt::format("{} takes {}", w.name, w.takes_count ? "at most one argument" : "no argument"));
    }
    MmsCommand c;
    c.verb = w.verb;
    if (w.verb == MmsVerb::get_stat) {
      if (tokens.size() != 2) return failed("getStat takes a stat name");
      // mms drops a name it does not know, as any line it cannot read (empty stats answer every known one).
      if (!MmsStats().stat(tokens[1])) return failed(fmt::format("getStat: no stat '{}'", tokens[1]));
      c.stat = std::string(tokens[1]);
    } else if (tokens.size() == 2) {
      c.count = integer(tokens[1]).value_or(0);  // as mms reads it: not a number is 0
    }
    return ParsedLine{c, {}};
  }
  return failed("unknown command");
}

}  // namespace

ParsedLine parse_mms_line(std::string_view line) {
  const std::vector<std::string_view> tokens = tokens_of(line);
  if (tokens.empty()) return failed("empty line");
  const std::string_view name = tokens[0];
  if (name == "setWall") return parse_wall(MmsVerb::set_wall, name, tokens);
  if (name == "clearWall") return parse_wall(MmsVerb::clear_wall, name, tokens);
  if (name == "setColor") return parse_set_color(tokens);
  if (name == "clearColor") return parse_cell_command(MmsVerb::clear_color, name, tokens, 3, "X Y");
  if (name == "clearText") return parse_cell_command(MmsVerb::clear_text, name, tokens, 3, "X Y");
  if (name == "setText" && line.starts_with("setText ")) return parse_set_text(line);
  if (name == "setText") return failed("setText takes X Y TEXT");
  if (name == "clearAllColor" || name == "clearAllText") {
    if (tokens.size() != 1) return failed(fmt::format("{} takes no argument", name));
    MmsCommand c;
    c.verb = name == "clearAllColor" ? MmsVerb::clear_all_color : MmsVerb::clear_all_text;
    return ParsedLine{c, {}};
  }
  return parse_answered(tokens);
}

bool has_answer(MmsVerb verb) {
  switch (verb) {
    case MmsVerb::set_wall:
    case MmsVerb::clear_wall:
    case MmsVerb::set_color:
    case MmsVerb::clear_color:
    case MmsVerb::clear_all_color:
    case MmsVerb::set_text:
    case MmsVerb::clear_text:
    case MmsVerb::clear_all_text: return false;
    default: return true;
  }
}

std::optional<std::string_view> mms_color_name(char letter) {
  for (const Color &c : kColors) {
    if (c.letter == letter) return c.name;
  }
  return std::nullopt;
}

std::optional<MmsRgb> mms_color_rgb(char letter) {
  for (const Color &c : kColors) {
    if (c.letter == letter) return c.rgb;
  }
  return std::nullopt;
}

void MmsStats::start_run() {
  current_turns_ = 0;
  current_distance_ = 0;
  current_effective_ = penalty_;
  total_effective_ += penalty_;
  penalty_ = 0.0F;
  started_run_ = true;
}

void MmsStats::add_distance(long long cells) {
  const float effective = cells > 2 ? static_cast<float>(cells) / 2.0F + 1.0F : static_cast<float>(cells);
  total_distance_ += cells;
  total_effective_ += effective;
  if (started_run_) {
    current_distance_ += cells;
    current_effective_ += effective;
  }
}

void MmsStats::add_turn() {
  ++total_turns_;
  if (started_run_) ++current_turns_;
}

void MmsStats::finish_run() {
  started_run_ = false;
  const float current = static_cast<float>(current_turns_) + current_effective_;
  const float best = static_cast<float>(best_turns_) + best_effective_;
  if (!solved_ || current < best) {
    best_turns_ = current_turns_;
    best_distance_ = current_distance_;
    best_effective_ = current_effective_;
  }
  solved_ = true;
}

void MmsStats::end_unfinished_run() { started_run_ = false; }

void MmsStats::penalize_for_reset() { penalty_ = 15.0F; }

std::optional<long long> MmsStats::best_run_distance() const { return solved_ ? std::optional(best_distance_) : std::nullopt; }
std::optional<int> MmsStats::best_run_turns() const { return solved_ ? std::optional(best_turns_) : std::nullopt; }
std::optional<float> MmsStats::best_run_effective_distance() const {
  return solved_ ? std::optional(best_effective_) : std::nullopt;
}

float MmsStats::score() const {
  if (!solved_) return 2000.0F;
  return best_effective_ + static_cast<float>(best_turns_) +
         0.1F * (total_effective_ + static_cast<float>(total_turns_));
}

std::optional<std::string> MmsStats::stat(std::string_view name) const {
  const auto number = [](auto v) -> std::string {
    if (!v) return "-1";
    return mms_number(static_cast<double>(*v));
  };
  if (name == "total-distance") return std::to_string(total_distance_);
  if (name == "total-turns") return std::to_string(total_turns_);
  if (name == "best-run-distance") return number(best_run_distance());
  if (name == "best-run-turns") return number(best_run_turns());
  if (name == "current-run-distance") return std::to_string(current_distance_);
  if (name == "current-run-turns") return std::to_string(current_turns_);
  if (name == "total-effective-distance") return mms_number(total_effective_);
  if (name == "best-run-effective-distance") return number(best_run_effective_distance());
  if (name == "current-run-effective-distance") return mms_number(current_effective_);
  if (name == "score") return mms_number(score());
  return std::nullopt;
}

std::string mms_number(double value) { return fmt::format("{:g}", value); }

}  // namespace app
