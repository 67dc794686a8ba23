#pragma once
// Where in an XML world file an element is, for located errors, and its numeric attributes
// read with their place (xml_format.cpp).

#include <charconv>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <tinyxml2.h>

#include "common/error.hpp"

namespace maze::xml {

struct Source {
  std::string_view text;
  const std::string &file;
  std::vector<std::size_t> line_starts;

  Source(std::string_view t, const std::string &f) : text(t), file(f) {
    line_starts.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '\n') line_starts.push_back(i + 1);
    }
  }

  // The element's line, and the column of `attribute=` on that line if it is there. Several
  // elements on one line are told apart by counting the earlier siblings of the same name.
  // With a cursor (elements of one name visited in document order), the tag is searched from
  // the one before on its line: N elements on one line cost O(line), not O(N * line).
  struct Cursor {
    int line = 0;
    std::size_t from = 0;
  };
  common::SourceLocation at(const tinyxml2::XMLElement &e, const char *attribute = nullptr,
                            Cursor *cursor = nullptr) const {
    const int line = e.GetLineNum();
    if (line < 1 || static_cast<std::size_t>(line) > line_starts.size()) return {file, 0, 0};
    const std::size_t begin = line_starts[static_cast<std::size_t>(line - 1)];
    const std::size_t end = static_cast<std::size_t>(line) < line_starts.size()
                                ? line_starts[static_cast<std::size_t>(line)]
                                : text.size();
    const std::string_view text_of_line = text.substr(begin, end - begin);
    if (cursor != nullptr && cursor->line != line) *cursor = Cursor{line, 0};
    std::size_t column = cursor == nullptr ? find_tag(text_of_line, e.Name(), earlier_on_same_line(e))
                                           : find_tag(text_of_line.substr(cursor->from), e.Name(), 0);
    if (cursor != nullptr && column != std::string_view::npos) cursor->from = (column += cursor->from) + 1;
    if (attribute != nullptr && column != std::string_view::npos) {
      column = text_of_line.find(fmt::format(" {}=", attribute), column);
      if (column != std::string_view::npos) ++column;
    }
    if (column == std::string_view::npos) return {file, line, 0};
    return {file, line, static_cast<int>(column + 1)};
  }

  static std::size_t earlier_on_same_line(const tinyxml2::XMLElement &e) {
    std::size_t n = 0;
    for (auto *p = e.PreviousSiblingElement(e.Name()); p != nullptr && p->GetLineNum() == e.GetLineNum();
         p = p->PreviousSiblingElement(e.Name())) {
      ++n;
    }
    return n;
  }

  // Where the (skip + 1)-th tag `<name` starts in the line.
  static std::size_t find_tag(std::string_view line, std::string_view name, std::size_t skip) {
    const std::string tag = fmt::format("<{}", name);
    for (std::size_t at = line.find(tag); at != std::string_view::npos; at = line.find(tag, at + 1)) {
      const std::size_t after = at + tag.size();
      const bool whole = after == line.size() || std::string_view(" \t\r\n/>").find(line[after]) != std::string_view::npos;
      if (!whole) continue;
      if (skip == 0) return at;
      --skip;
    }
    return std::string_view::npos;
  }

  common::InputError error(const tinyxml2::XMLElement &e, const char *attribute, std::string message) const {
    return common::InputError(at(e, attribute), std::move(message));
  }
};

inline std::optional<double> number(const tinyxml2::XMLElement &e, const char *name, const Source &src,
                                    bool required) {
  const char *value = e.Attribute(name);
  if (value == nullptr) {
    if (required) throw src.error(e, nullptr, fmt::format("<{}> needs the attribute {}", e.Name(), name));
    return std::nullopt;
  }
  std::string_view text(value);
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  double result = 0.0;
  const auto [stop, ec] = std::from_chars(text.data(), text.data() + text.size(), result);
  const std::string shown(std::string_view(value).substr(0, 20));
  if (ec != std::errc() || stop != text.data() + text.size() || text.empty()) {
    throw src.error(e, name, fmt::format("{} is not a number: '{}'", name, shown));
  }
  if (!std::isfinite(result) || std::abs(result) > 1e9) {
    const std::string_view unit = std::string_view(name) == "theta" ? "radians" : "metres";
    throw src.error(e, name, fmt::format("{} is not a finite number of {}: '{}'", name, unit, shown));
  }
  return result;
}

// tinyxml2's XML_ERROR_MISMATCHED_ELEMENT as "mismatched element".
inline std::string error_name(tinyxml2::XMLError id) {
  std::string name = tinyxml2::XMLDocument::ErrorIDToName(id);
  if (name.starts_with("XML_ERROR_")) name.erase(0, 10);
  for (char &c : name) c = c == '_' ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return name;
}

inline const tinyxml2::XMLElement &parse(tinyxml2::XMLDocument &doc, const Source &src) {
  if (doc.Parse(src.text.data(), src.text.size()) != tinyxml2::XML_SUCCESS) {
    throw common::InputError(common::SourceLocation{src.file, doc.ErrorLineNum(), 0},
                             fmt::format("not well-formed XML: {}", error_name(doc.ErrorID())));
  }
  const tinyxml2::XMLElement *root = doc.RootElement();
  if (root == nullptr) throw common::InputError(common::SourceLocation{src.file, 0, 0}, "no XML element: expected <world>");
  if (std::string_view(root->Name()) != "world") {
    throw src.error(*root, nullptr, fmt::format("the root element is <{}>; expected <world>", root->Name()));
  }
  return *root;
}

}  // namespace maze::xml
