// batch --shard K/N and batch merge (see app/batch/batch.hpp).

#include <cmath>
#include <fstream>
#include <optional>
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

// The fields' texts of one CSV line (common/csv.hpp); nothing when a quote is left open.
std::optional<std::vector<std::string>> csv_texts(std::string_view line) {
  const std::optional<std::vector<common::CsvField>> fields = common::csv_fields(line);
  if (!fields) return std::nullopt;
  std::vector<std::string> texts;
  for (const common::CsvField &f : *fields) texts.push_back(f.text);
  return texts;
}

// One row from its fields (kBatchCsvHeader's columns); nothing when a number does not parse.
std::optional<BatchRow> row_from(const std::vector<std::string> &f) {
  BatchRow row;
  row.world = f[0];
  row.error = f[9];
  row.ran = !f[1].empty();
  row.ok = row.ran && row.error.empty();
  if (!row.ran) return row;
  // As exit_status: a run that ended other than done (or at a step limit, which the CSV does
  // not say was the user's) did not map its maze, whatever part it was merged from.
  row.ok = row.ok && (f[8] == robot::to_string(robot::EndReason::done) ||
                      f[8] == robot::to_string(robot::EndReason::max_steps));
  const std::optional<int> moves = common::parse_number<int>(f[2]);
  const std::optional<double> coverage = common::parse_number<double>(f[3]);
  const std::optional<double> accuracy = common::parse_number<double>(f[4]);
  const std::optional<double> ms = common::parse_number<double>(f[7]);
  if (!moves || !coverage || !accuracy || !ms) return std::nullopt;
  row.size = f[1];
  row.moves = *moves;
  row.coverage_percent = *coverage;
  row.wall_accuracy_percent = *accuracy;
  row.goal = f[5];
  row.speed_run = f[6];
  row.ms = *ms;
  row.end = f[8];
  return row;
}

void read_one(const std::string &file, std::vector<BatchRow> &rows) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw common::InputError(common::SourceLocation{file, 0, 0}, "cannot read the file");
  std::string line;
  if (!std::getline(in, line) || line != kBatchCsvHeader) {
    throw common::InputError(common::SourceLocation{file, 1, 0},
                             fmt::format("not a batch CSV (the first line must be '{}')", kBatchCsvHeader));
  }
  for (int number = 2; std::getline(in, line); ++number) {
    // A quoted field may hold a newline (a path with one): the record goes on on the next line.
    const int first = number;
    std::optional<std::vector<std::string>> fields = csv_texts(line);
    std::string more;
    while (!fields && std::getline(in, more)) {
      ++number;
      line += '\n';
      line += more;
      fields = csv_texts(line);
    }
    const std::optional<BatchRow> row =
        fields && fields->size() == 10 ? row_from(*fields) : std::optional<BatchRow>();
    if (!row) {
      throw common::InputError(common::SourceLocation{file, first, 0},
                               fmt::format("not a batch CSV row (10 fields: {})", kBatchCsvHeader));
    }
    rows.push_back(*row);
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
  for (const std::string &file : files) read_one(file, rows);
  return rows;
}

}  // namespace app
