// libFuzzer target: batch merge's CSV reader (app::read_batch_csv_text, common::CsvRecords).
// A part it rejects must be rejected with common::InputError (anything else escapes and
// libFuzzer reports it). The records of the text must cover its lines in order, and a
// single line must read as csv_fields reads it.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/batch/batch.hpp"
#include "common/csv.hpp"
#include "common/error.hpp"

namespace {

// The records start on rising lines and the last ends with the text.
void check_records(std::string_view text) {
  common::CsvRecords records(text);
  int line = 0;
  while (!records.done()) {
    const common::CsvRecord record = records.next();
    if (record.line <= line) std::abort();
    line = record.line;
    if (record.open_quote && !records.done()) std::abort();
  }
}

// A line without a line end reads as csv_fields reads it.
void check_one_line(std::string_view text) {
  const std::string_view line = text.substr(0, text.find('\n'));
  const std::optional<std::vector<common::CsvField>> fields = common::csv_fields(line);
  const common::CsvRecord record = common::CsvRecords(line).next();
  if (fields.has_value() == record.open_quote.has_value()) std::abort();
  if (!fields) return;
  if (fields->size() != record.fields.size()) std::abort();
  for (std::size_t i = 0; i < fields->size(); ++i) {
    if ((*fields)[i].text != record.fields[i].text || (*fields)[i].column != record.fields[i].column) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char *>(data), size);
  check_records(text);
  check_one_line(text);
  try {
    app::read_batch_csv_text("fuzz.csv", text);
  } catch (const common::InputError &e) {
    if (e.diagnostic().empty()) std::abort();
  }
  return 0;
}
