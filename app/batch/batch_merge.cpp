// batch --shard K/N and batch merge (see app/batch/batch.hpp).

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "common/csv.hpp"
#include "common/input_file.hpp"
#include "common/parse_number.hpp"
#include "app/batch/batch.hpp"
#include "common/error.hpp"

namespace app {
namespace {

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

// The headers of the maze batch and the mms batch before every kind wrote one row: their rows
// are read as that kind's, by their columns' names, a column the row has no place for dropped
// (mms's lines, distances and turns); a row ran when its size is given.
struct OlderHeader {
  std::string_view text;
  RunKind kind;
};
constexpr OlderHeader kOlderHeaders[] = {
    {"world,size,moves,coverage,wall_accuracy,goal,speed_run,ms,end,error", RunKind::maze},
    {"world,size,end,lines,moves,goal,total_distance,total_turns,total_effective_distance,best_run_distance,"
     "best_run_turns,best_run_effective_distance,score,ms,error",
     RunKind::mms},
};

// How a part's rows read: its header's columns, and the older header it is, if one.
struct PartLayout {
  std::vector<std::string> names;
  const OlderHeader *older = nullptr;
};

std::vector<std::string> split_names(std::string_view header) {
  std::vector<std::string> names;
  for (std::size_t start = 0;;) {
    const std::size_t comma = header.find(',', start);
    names.emplace_back(header.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return names;
    start = comma + 1;
  }
}

PartLayout layout_of(const std::string &file, const std::string &header) {
  if (header == batch_csv_header()) return {split_names(header), nullptr};
  for (const OlderHeader &older : kOlderHeaders) {
    if (header == older.text) return {split_names(header), &older};
  }
  throw common::InputError(common::SourceLocation{file, 1, 0},
                           fmt::format("not a batch CSV (the first line must be '{}')", batch_csv_header()));
}

BatchRow row_in(const PartLayout &layout, const std::vector<common::CsvField> &fields, const RowPlace &at) {
  BatchRow row = parse_batch_row(layout.names, fields, layout.older ? layout.older->kind : RunKind::maze, at);
  if (layout.older) {
    row.ran = !row.size.empty();
    if (!row.ran) row.end.clear();  // an mms row that did not run said "failed" there
    row.ok = batch_row_ok(row);
  }
  return row;
}

// A part's text as its rows are read: a UTF-8 byte order mark before the header dropped,
// CRLF line ends read as LF.
std::string lf_text(std::string_view s) {
  if (s.starts_with(kUtf8Bom)) s.remove_prefix(kUtf8Bom.size());
  std::string lf;
  lf.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!(s[i] == '\r' && i + 1 < s.size() && s[i + 1] == '\n')) lf += s[i];
  }
  return lf;
}

// The whole file (within common::kCsvLimits), as lf_text has it.
std::string part_text(const std::string &file) {
  try {
    // The header is looked at as soon as it has come: a file that is no batch CSV is not read on.
    const auto header = [&file](std::string_view line) {
      if (line.ends_with('\r')) line.remove_suffix(1);
      layout_of(file, lf_text(line));
    };
    return lf_text(common::read_text(file, "batch CSV", common::kCsvLimits, header));  // "" when empty: no header
  } catch (const common::InputError &e) {
    if (!e.where().file.empty()) throw;  // not a batch CSV
    throw common::InputError(common::SourceLocation{file, 0, 0}, "cannot read the file");
  }
}

// The rows of one part's text. A quoted field may hold a line end (a path with one): its
// record goes on on the next line; a quote never closed is named where it opened.
void read_rows(const std::string &file, const std::string &text, std::vector<BatchRow> &rows) {
  const std::size_t header_end = std::min(text.find('\n'), text.size());
  const PartLayout layout = layout_of(file, text.substr(0, header_end));
  common::CsvRecords records(std::string_view(text).substr(std::min(header_end + 1, text.size())), 2);
  while (!records.done()) {
    const common::CsvRecord record = records.next();
    if (record.open_quote) {
      throw common::InputError(common::SourceLocation{file, record.open_quote->first, record.open_quote->second},
                               "not a batch CSV row: the quoted field that opens here is never closed");
    }
    if (record.fields.size() != layout.names.size()) {
      throw common::InputError(common::SourceLocation{file, record.line, 0},
                               fmt::format("not a batch CSV row ({} fields: {})", layout.names.size(),
                                           layout.older ? layout.older->text : std::string_view(batch_csv_header())));
    }
    rows.push_back(row_in(layout, record.fields, RowPlace{file, record.line}));
  }
}

// A part given twice would count its rows twice: the same file (by its real path, through
// links), or the same rows as an earlier part (a copy). Parts with no rows (a shard of fewer
// worlds than parts) may repeat.
void refuse_repeated_part(const std::vector<std::string> &files, const std::vector<std::string> &texts,
                          std::size_t i) {
  std::error_code ec;
  for (std::size_t j = 0; j < i; ++j) {
    if (std::filesystem::equivalent(files[j], files[i], ec)) {
      throw common::InputError(common::SourceLocation{files[i], 0, 0},
                               fmt::format("is {} again (the same file): its rows would count twice", files[j]));
    }
    const std::size_t header_end = texts[i].find('\n');
    const bool has_rows = header_end != std::string::npos && header_end + 1 < texts[i].size();
    if (has_rows && texts[i] == texts[j]) {
      throw common::InputError(common::SourceLocation{files[i], 0, 0},
                               fmt::format("holds the same rows as {}: its rows would count twice", files[j]));
    }
  }
}

}  // namespace

Shard parse_shard(const std::string &text) {
  const std::size_t slash = text.find('/');
  const std::optional<int> k = slash == std::string::npos ? std::nullopt : common::parse_number<int>(std::string_view(text).substr(0, slash));
  const std::optional<int> n = slash == std::string::npos ? std::nullopt : common::parse_number<int>(std::string_view(text).substr(slash + 1));
  if (!k || !n || *n < 1 || *k < 1 || *k > *n) {
    throw common::InputError(fmt::format("--shard must be K/N with 1 <= K <= N, e.g. 2/8 (got '{}')", text));
  }
  return Shard{*k, *n};
}

std::vector<std::string> shard_of(const std::vector<std::string> &worlds, Shard shard) {
  const auto part_start = [&](int k) {
    return static_cast<std::size_t>(static_cast<long long>(worlds.size()) * (k - 1) / shard.count);
  };
  return {worlds.begin() + static_cast<std::ptrdiff_t>(part_start(shard.index)),
          worlds.begin() + static_cast<std::ptrdiff_t>(part_start(shard.index + 1))};
}

std::vector<BatchRow> read_batch_csvs(const std::vector<std::string> &files) {
  std::vector<BatchRow> rows;
  std::vector<std::string> texts;
  for (std::size_t i = 0; i < files.size(); ++i) {
    texts.push_back(part_text(files[i]));
    refuse_repeated_part(files, texts, i);
    read_rows(files[i], texts[i], rows);
  }
  return rows;
}

std::vector<BatchRow> read_batch_csv_text(const std::string &file, std::string_view text) {
  std::vector<BatchRow> rows;
  read_rows(file, lf_text(text), rows);
  return rows;
}

}  // namespace app
