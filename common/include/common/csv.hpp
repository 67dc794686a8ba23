#pragma once
// CSV as RFC 4180 has it, the one form of every CSV file the program writes or reads
// (batch.csv, compare.csv, trace.csv, plan.csv, mms stats, map-log's input):
//
//   world,moves,error\n          fields separated by ',', a row ended by "\n"
//   "a,b.txt",12,""""\n          a field holding ',', '"', CR or LF is quoted, a '"' in it
//                                doubled; any other field is written as it is
//
// A reader also takes CRLF line ends (the CR is dropped) and quoted fields anywhere.
// csv_fields reads one line; CsvRecords reads a text whose quoted fields may hold line ends.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
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

// One record of a CSV text (CsvRecords): its fields, the line it starts on, and, when the
// text ends inside a quoted field, the line and column (from 1) where that quote opened.
struct CsvRecord {
  std::vector<CsvField> fields;
  int line = 1;
  std::optional<std::pair<int, int>> open_quote;
};

// The records of a CSV text one after another. A record ends at a "\n" outside quotes (a
// quoted field may hold one: a path with a line end), its CR before it dropped; each byte is
// looked at once, so a quote never closed costs no more than the text's length: its record
// runs to the end of the text and names where the quote opened. A field's column counts
// from the start of the line it starts on.
class CsvRecords {
 public:
  explicit CsvRecords(std::string_view text, int first_line = 1) : text_(text), line_(first_line) {}
  bool done() const { return pos_ >= text_.size(); }

  CsvRecord next() {
    CsvRecord record{std::vector<CsvField>(1), line_, std::nullopt};
    bool quoted = false;
    std::size_t line_start = pos_;
    for (; pos_ < text_.size(); ++pos_) {
      const char c = text_[pos_];
      const bool last = pos_ + 1 == text_.size();
      if (c == '\n') {
        ++line_;
        line_start = pos_ + 1;
        if (!quoted) {
          ++pos_;
          record.open_quote.reset();
          return record;
        }
        record.fields.back().text += c;
      } else if (quoted && c == '"' && !last && text_[pos_ + 1] == '"') {
        record.fields.back().text += '"';
        ++pos_;
      } else if (c == '"') {
        quoted = !quoted;
        if (quoted) record.open_quote = std::pair{line_, static_cast<int>(pos_ - line_start) + 1};
      } else if (c == ',' && !quoted) {
        record.fields.push_back(CsvField{"", static_cast<int>(pos_ - line_start) + 2});
      } else if (!(c == '\r' && !quoted && (last || text_[pos_ + 1] == '\n'))) {
        record.fields.back().text += c;
      }
    }
    if (!quoted) record.open_quote.reset();
    return record;
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_;
};

}  // namespace common
