#pragma once
// The blank-separated tokens of one line of a text world format (num_format.cpp,
// solids_format.cpp), each with its column for located errors, and a token as an error shows it.

#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

namespace maze {

struct LineToken {
  std::string_view text;
  std::size_t column;  // from 0
};

// The tokens of `line` separated by blanks and tabs, at most `most` of them (a reader that
// takes N asks for N + 1 to tell "too many").
inline std::vector<LineToken> line_tokens(std::string_view line,
                                          std::size_t most = std::numeric_limits<std::size_t>::max()) {
  std::vector<LineToken> tokens;
  std::size_t i = 0;
  while (i < line.size() && tokens.size() < most) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i == line.size()) break;
    const std::size_t begin = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    tokens.push_back({line.substr(begin, i - begin), begin});
  }
  return tokens;
}

// A token as an error message quotes it: its first 20 bytes, a byte outside printable ASCII
// as \xHH, "..." when it is longer.
inline std::string shown_token(std::string_view token) {
  std::string out;
  for (const char c : token.substr(0, 20)) {
    const auto u = static_cast<unsigned char>(c);
    out += (u >= 0x20 && u < 0x7f) ? std::string(1, c) : fmt::format("\\x{:02x}", u);
  }
  return token.size() > 20 ? out + "..." : out;
}

}  // namespace maze
