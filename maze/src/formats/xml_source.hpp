#pragma once
// Where in an XML world file an element and its attributes are, for located errors, and its
// numeric attributes read with their place (xml_format.cpp, xml_solids.cpp).

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "maze/world/maze.hpp"
#include "xml_document.hpp"

namespace maze::xml {

struct Source {
  std::string_view text;
  const std::string &file;

  Source(std::string_view t, const std::string &f) : text(t), file(f) {}

  // The element's place, or the place of its attribute `attribute=` when the start tag holds
  // it (on the tag's line or a later one).
  common::SourceLocation at(const Element &e, const char *attribute = nullptr) const {
    const std::size_t found = attribute == nullptr ? std::string_view::npos : attribute_offset(e, attribute);
    if (found == std::string_view::npos) return {file, e.line(), e.column()};
    const std::string_view before = text.substr(e.offset(), found - e.offset());
    const std::size_t newline = before.rfind('\n');
    if (newline == std::string_view::npos) return {file, e.line(), e.column() + characters(before)};
    const int lines = static_cast<int>(std::count(before.begin(), before.end(), '\n'));
    return {file, e.line() + lines, 1 + characters(before.substr(newline + 1))};
  }

  // The byte offset of the attribute's name in the element's start tag, or npos.
  std::size_t attribute_offset(const Element &e, std::string_view attribute) const {
    constexpr std::string_view kBlank = " \t\r\n";
    std::size_t i = e.offset();
    if (i >= text.size() || text[i] != '<') return std::string_view::npos;
    i = text.find_first_of(" \t\r\n/>", i);
    while (i < text.size()) {
      i = text.find_first_not_of(kBlank, i);
      if (i == std::string_view::npos || text[i] == '/' || text[i] == '>') return std::string_view::npos;
      const std::size_t name_end = text.find_first_of(" \t\r\n=", i);
      if (name_end == std::string_view::npos) return std::string_view::npos;
      if (text.substr(i, name_end - i) == attribute) return i;
      const std::size_t quote = text.find_first_of("\"'", name_end);
      if (quote == std::string_view::npos) return std::string_view::npos;
      const std::size_t close = text.find(text[quote], quote + 1);
      if (close == std::string_view::npos) return std::string_view::npos;
      i = close + 1;
    }
    return std::string_view::npos;
  }

  // UTF-8 characters in the bytes (the parser counts columns in characters).
  static int characters(std::string_view bytes) {
    return static_cast<int>(std::count_if(bytes.begin(), bytes.end(), [](char c) {
      return (static_cast<unsigned char>(c) & 0xC0u) != 0x80u;
    }));
  }

  common::InputError error(const Element &e, const char *attribute, std::string message) const {
    return common::InputError(at(e, attribute), std::move(message));
  }
};

inline std::optional<double> number(const Element &e, const char *name, const Source &src, bool required) {
  const std::optional<std::string_view> value = e.attribute(name);
  if (!value) {
    if (required) throw src.error(e, nullptr, fmt::format("<{}> needs the attribute {}", e.name(), name));
    return std::nullopt;
  }
  std::string_view text = *value;
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  double result = 0.0;
  const auto [stop, ec] = std::from_chars(text.data(), text.data() + text.size(), result);
  const std::string shown(value->substr(0, 20));
  if (ec != std::errc() || stop != text.data() + text.size() || text.empty()) {
    throw src.error(e, name, fmt::format("{} is not a number: '{}'", name, shown));
  }
  if (!std::isfinite(result) || std::abs(result) > 1e9) {
    const std::string_view unit = std::string_view(name) == "theta" ? "radians" : "metres";
    throw src.error(e, name, fmt::format("{} is not a finite number of {}: '{}'", name, unit, shown));
  }
  return result;
}

// The document's root, which must be <world>.
inline Element world_of(const Document &doc, const Source &src) {
  const Element root = doc.root();
  if (root.name() != "world") {
    throw src.error(root, nullptr, fmt::format("the root element is <{}>; expected <world>", root.name()));
  }
  return root;
}

// A colour component of a <landmark>: a number in [0, 1], 1 when left out.
inline double colour(const xml::Element &e, const char *name, const Source &src) {
  const double v = number(e, name, src, false).value_or(1.0);
  if (v < 0.0 || v > 1.0) throw src.error(e, name, fmt::format("{} must be 0 to 1, got {}", name, v));
  return v;
}

// <landmark x y [height] [red green blue]/>: x and y required, anywhere (an object in the
// world, not a cell: the course's stand at the arena's corners, on or beyond its edge); height
// positive (the course's 1.5 m when left out).
inline Landmark read_landmark(const xml::Element &e, const Source &src) {
  Landmark l;
  l.x_m = *number(e, "x", src, true);
  l.y_m = *number(e, "y", src, true);
  l.height_m = number(e, "height", src, false).value_or(1.5);
  if (!(l.height_m > 0.0)) throw src.error(e, "height", fmt::format("height must be positive, got {}", l.height_m));
  l.red = colour(e, "red", src);
  l.green = colour(e, "green", src);
  l.blue = colour(e, "blue", src);
  return l;
}

}  // namespace maze::xml
