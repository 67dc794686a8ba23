#include "maze/world/format_detector.hpp"

#include <fmt/format.h>

#include "common/error.hpp"
#include "maze/formats/solids_format.hpp"

namespace maze {
namespace {

constexpr std::string_view kBom = "\xEF\xBB\xBF";
constexpr std::string_view kWebots = "#VRML_SIM";
constexpr std::size_t kLongestKeyword = 8;

constexpr std::string_view kExpected =
    "expected a text map (first line 'o---o...'), num lines 'X Y N E S W', XML '<world>', a room file ('boundary XS "
    "XE YS YE', 'rect ...') or a 256-byte binary .maz";

bool ends_word(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '#'; }

bool is_room_keyword(std::string_view word) {
  for (const std::string_view k : kRoomKeywords) {
    if (word == k) return true;
  }
  return false;
}

// Whether `text` may still become `whole` (it is a proper beginning of it).
bool may_become(std::string_view text, std::string_view whole) {
  return text.size() < whole.size() && whole.starts_with(text);
}

}  // namespace

void FormatDetector::cannot_tell(int line, int column, std::string_view why) const {
  throw common::InputError(common::SourceLocation{file_, line, column}, fmt::format("cannot tell the format: {}", why));
}

// The BOM and a Webots first line; false while the bytes so far may still be either.
bool FormatDetector::look_at_start(std::string_view text, bool at_end) {
  if (text.empty() && at_end) {
    throw common::InputError(common::SourceLocation{file_, 0, 0}, "the file is empty; expected a maze");
  }
  if (!at_end && (text.empty() || may_become(text, kBom))) return false;
  if (text.starts_with(kBom)) {
    pos_ = line_start_ = kBom.size();
    maz_possible_ = false;
  }
  const std::string_view body = text.substr(pos_);
  if (!at_end && may_become(body, kWebots)) return false;
  if (body.starts_with(kWebots)) {
    throw common::InputError(common::SourceLocation{file_, 1, 1},
                             "a Webots .wbt world, which maze_mapper writes but does not read: use the text map, "
                             "num or XML world it was made from");
  }
  started_ = true;
  return true;
}

// The format the first meaningful line, which starts at pos_, tells.
std::optional<Format> FormatDetector::first_meaningful(std::string_view text, bool at_end) const {
  const char c = text[pos_];
  if (c == '<') return Format::xml;
  if (c >= '0' && c <= '9') return Format::num;
  const auto column = static_cast<int>(pos_ - line_start_) + 1;
  if ((c == 'o' || c == '+') && column == 1) return Format::text_map;
  std::size_t end = pos_;
  while (end < text.size() && end - pos_ <= kLongestKeyword && !ends_word(text[end])) ++end;
  if (end == text.size() && end - pos_ <= kLongestKeyword && !at_end) return std::nullopt;  // the word may go on
  if (is_room_keyword(text.substr(pos_, end - pos_))) return Format::room;
  cannot_tell(line_, column, kExpected);
}

std::optional<Format> FormatDetector::look(std::string_view text, bool at_end) {
  if (!started_ && !look_at_start(text, at_end)) return std::nullopt;
  const auto refuse_past_limit = [this] {
    if (pos_ < within_) return;
    cannot_tell(line_, 1, fmt::format("no line but blank and comment lines in the first {}; {}",
                                      common::size_text(within_), kExpected));
  };
  while (pos_ < text.size()) {
    refuse_past_limit();
    const char c = text[pos_];
    if (in_comment_) {
      const std::size_t end = text.find('\n', pos_);
      pos_ = end == std::string_view::npos ? text.size() : end;
      in_comment_ = end == std::string_view::npos;
    } else if (c == '\n') {
      ++line_;
      line_start_ = ++pos_;
    } else if (c == '\t' || c == '\r' || c == ' ') {
      maz_possible_ = maz_possible_ && c != ' ';
      ++pos_;
    } else if (maz_possible_ && c >= '\x01' && c <= '\x0F') {
      return Format::maz;
    } else if (c == '#') {
      maz_possible_ = false;
      in_comment_ = true;
      ++pos_;
    } else {
      return first_meaningful(text, at_end);
    }
  }
  refuse_past_limit();
  if (at_end) cannot_tell(1, 1, kExpected);
  return std::nullopt;
}

}  // namespace maze
