#pragma once
// Text as XML character data or an attribute value: & < > " replaced by their entities (the
// SVG plots, the arena XML writer).

#include <string>
#include <string_view>

namespace common {

inline std::string xml_escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace common
