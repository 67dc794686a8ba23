// batch --shard K/N and batch merge (see app/batch/batch.hpp).

#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "common/parse_number.hpp"
#include "common/csv.hpp"
#include "app/batch/batch.hpp"
#include "common/error.hpp"

namespace app {
namespace {

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

// Where a field of a part is: the file, the line its record starts on.
struct RowPlace {
  const std::string &file;
  int line = 0;
};

common::InputError field_error(const RowPlace &at, const common::CsvField &field, const std::string &what) {
  return common::InputError(common::SourceLocation{at.file, at.line, field.column},
                            fmt::format("{} (got '{}')", what, field.text));
}

// A number of the row within [least, most]; a located error names the column otherwise.
template <typename Number>
Number field_number(const RowPlace &at, const common::CsvField &field, Number least, Number most,
                    const std::string &what) {
  const std::optional<Number> v = common::parse_number<Number>(field.text);
  if (!v || *v < least || *v > most) throw field_error(at, field, what);
  return *v;
}

// One row from its fields (kBatchCsvHeader's columns).
BatchRow row_from(const RowPlace &at, const std::vector<common::CsvField> &f) {
  BatchRow row;
  row.world = f[0].text;
  row.error = f[9].text;
  row.ran = !f[1].text.empty();
  row.ok = row.ran && row.error.empty();
  if (!row.ran) return row;
  // As exit_status: a run that ended other than done (or at a step limit, which the CSV does
  // not say was the user's) did not map its maze, whatever part it was merged from.
  row.ok = row.ok && (f[8].text == robot::to_string(robot::EndReason::done) ||
                      f[8].text == robot::to_string(robot::EndReason::max_steps));
  constexpr double kMostMs = 1e12;  // 30 years of one run
  row.size = f[1].text;
  row.moves = field_number<long>(at, f[2], 0, std::numeric_limits<int>::max(), "moves must be a whole number from 0");
  row.coverage_percent = field_number(at, f[3], 0.0, 100.0, "coverage must be a percentage from 0 to 100");
  row.wall_accuracy_percent = field_number(at, f[4], 0.0, 100.0, "wall_accuracy must be a percentage from 0 to 100");
  row.goal = f[5].text;
  row.speed_run = f[6].text;
  row.ms = field_number(at, f[7], 0.0, kMostMs, "ms must be a number of milliseconds from 0");
  row.end = f[8].text;
  return row;
}

// The whole file; a UTF-8 byte order mark before the header is dropped, CRLF line ends read as LF.
std::string part_text(const std::string &file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw common::InputError(common::SourceLocation{file, 0, 0}, "cannot read the file");
  std::ostringstream text;
  text << in.rdbuf();  // nothing for an empty file: its header is then missing
  std::string s = text.str();
  if (std::string_view(s).starts_with(kUtf8Bom)) s.erase(0, kUtf8Bom.size());
  std::string lf;
  lf.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!(s[i] == '\r' && i + 1 < s.size() && s[i + 1] == '\n')) lf += s[i];
  }
  return lf;
}

// The rows of one part's text.
void read_rows(const std::string &file, const std::string &text, std::vector<BatchRow> &rows) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line != kBatchCsvHeader) {
    throw common::InputError(common::SourceLocation{file, 1, 0},
                             fmt::format("not a batch CSV (the first line must be '{}')", kBatchCsvHeader));
  }
  for (int number = 2; std::getline(in, line); ++number) {
    // A quoted field may hold a newline (a path with one): the record goes on on the next line.
    const RowPlace at{file, number};
    std::optional<std::vector<common::CsvField>> fields = common::csv_fields(line);
    std::string more;
    while (!fields && std::getline(in, more)) {
      ++number;
      line += '\n';
      line += more;
      fields = common::csv_fields(line);
    }
    if (!fields || fields->size() != 10) {
      throw common::InputError(common::SourceLocation{file, at.line, 0},
                               fmt::format("not a batch CSV row (10 fields: {})", kBatchCsvHeader));
    }
    rows.push_back(row_from(at, *fields));
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

}  // namespace app
