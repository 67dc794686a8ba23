#pragma once
// CSV as RFC 4180 has it, the one form of every CSV file the program writes or reads
// (batch.csv, compare.csv, trace.csv, plan.csv, mms stats, map-log's input):
//
//   world,moves,error\n          fields separated by ',', a row ended by "\n"
//   "a,b.txt",12,""""\n          a field holding ',', '"', CR or LF is quoted, a '"' in it
//                                doubled; any other field is written as it is
//
// A reader also takes CRLF line ends (the CR is dropped) and quoted fields anywhere.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace common {

// The field as a CSV row holds it: quoted only when it must be.
inline std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + '"';
}

// A field of a line read back: its text (unquoted) and the 1-based column it starts at.
struct CsvField {
  std::string text;
  int column = 1;
};

// The fields of one line (without its "\n"; a trailing CR is dropped). Nothing when a quote
// is left open (a quoted field across lines is not read).
inline std::optional<std::vector<CsvField>> csv_fields(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  std::vector<CsvField> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back().text += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.push_back(CsvField{"", static_cast<int>(i) + 2});
    } else {
      fields.back().text += c;
    }
  }
  if (quoted) return std::nullopt;
  return fields;
}

}  // namespace common
