#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli_runner.hpp"
#include "common/atomic_file.hpp"
#include "common/csv.hpp"
#include "common/error.hpp"
#include "common/input_file.hpp"
#include "common/fixed_decimal.hpp"
#include "common/parse_number.hpp"
#include "common/random.hpp"
#include "test_values.hpp"

namespace {

std::vector<std::string> texts(std::string_view line) {
  const std::optional<std::vector<common::CsvField>> fields = common::csv_fields(line);
  std::vector<std::string> out;
  if (!fields) return out;
  for (std::size_t i = 0; i < fields->size(); ++i) out.push_back((*fields)[i].text);
  return out;
}

}  // namespace

TEST_CASE("parse_number: the whole text is the number, in the type's range, finite") {
  CHECK(common::parse_number<int>("42") == 42);
  CHECK(common::parse_number<int>("-7") == -7);
  CHECK(common::parse_number<double>("0.25") == 0.25);
  CHECK(common::parse_number<double>("1e-3") == 0.001);
  CHECK_FALSE(common::parse_number<int>(""));
  CHECK_FALSE(common::parse_number<int>("+3"));     // no '+'
  CHECK_FALSE(common::parse_number<int>(" 3"));     // no blanks
  CHECK_FALSE(common::parse_number<int>("3 "));
  CHECK_FALSE(common::parse_number<int>("3x"));
  CHECK_FALSE(common::parse_number<int>("2.5"));    // not whole
  CHECK_FALSE(common::parse_number<int>("4294967299"));  // past int: refused, not wrapped
  CHECK_FALSE(common::parse_number<std::uint64_t>("-1"));
  CHECK(common::parse_number<std::uint64_t>("18446744073709551615") == UINT64_MAX);
  CHECK_FALSE(common::parse_number<double>("inf"));
  CHECK_FALSE(common::parse_number<double>("nan"));
  CHECK_FALSE(common::parse_number<double>("1e400"));
  CHECK(common::parse_number_trimmed<int>(" 3\t") == 3);
  CHECK(std::isinf(common::parse_real("-inf").value()));
  CHECK(std::isnan(common::parse_real("nan").value()));
  CHECK_FALSE(common::parse_real("two"));
}

TEST_CASE("csv_field quotes only what must be quoted, as RFC 4180 has it") {
  CHECK(common::csv_field("worlds/a.txt") == "worlds/a.txt");
  CHECK(common::csv_field("") == "");
  CHECK(common::csv_field("a,b") == "\"a,b\"");
  CHECK(common::csv_field("say \"hi\"") == "\"say \"\"hi\"\"\"");
  CHECK(common::csv_field("two\nlines") == "\"two\nlines\"");
  CHECK(common::csv_field("cr\r") == "\"cr\r\"");
}

TEST_CASE("csv_fields reads back what csv_field writes, with each field's column") {
  const std::vector<std::string> fields{"a,b", "", "say \"hi\"", "plain", "x\ny"};
  std::string line;
  for (const std::string &f : fields) {
    if (!line.empty()) line += ',';
    line += common::csv_field(f);
  }
  CHECK(texts(line) == fields);
  CHECK(texts("1,2,3\r") == std::vector<std::string>{"1", "2", "3"});  // CRLF
  CHECK(texts("") == std::vector<std::string>{""});
  CHECK(texts("a,") == std::vector<std::string>{"a", ""});
  const std::vector<common::CsvField> located = common::csv_fields("t, x,\"y,z\",w").value();
  REQUIRE(located.size() == 4);
  CHECK(located[1].column == 3);
  CHECK(located[2].column == 6);
  CHECK(located[3].column == 12);
  CHECK_FALSE(common::csv_fields("\"open,quote"));
}

TEST_CASE("append_fixed and append_int write what fmt writes, byte for byte") {
  const auto fixed = [](double v, int decimals) {
    std::string text;
    common::append_fixed(text, v, decimals);
    return text;
  };
  // Ties in binary (x.5 at the last decimal), signs, zeros, carries, the fallbacks.
  for (const double v : {0.0, -0.0, 0.5, 1.5708, -1.5708, 0.03125, -0.03125, 0.00005, -0.00004, 9.99995, 0.99999,
                         123456.78915, 2.5e-5, 1e12, -3e9, std::nan(""), kInf, -kInf, 0.0625, 1.0 / 3.0}) {
    for (int decimals = 0; decimals <= 6; ++decimals) {
      CHECK_MESSAGE(fixed(v, decimals) == fmt::format("{:.{}f}", v, decimals), v, " ", decimals);
    }
  }
  common::Rng random(7);
  int wrong = 0;
  for (int i = 0; i < 200000; ++i) {
    const double v = (random.uniform(0.0, 1.0) - 0.5) * std::pow(10.0, random.uniform(-6.0, 7.0));
    for (const int decimals : {3, 4}) wrong += fixed(v, decimals) != fmt::format("{:.{}f}", v, decimals) ? 1 : 0;
  }
  CHECK(wrong == 0);
  std::string ints;
  common::append_int(ints, std::int64_t{-1234567890123});
  common::append_int(ints, 0);
  CHECK(ints == "-12345678901230");
}

TEST_CASE("CsvRecords: a quoted field holds a line end; a quote never closed names where it opened") {
  common::CsvRecords records("a,\"b\nc\",d\r\ne,f\n\"g,h\nx\ny");
  common::CsvRecord r = records.next();
  REQUIRE(r.fields.size() == 3);
  CHECK(r.fields[1].text == "b\nc");
  CHECK(r.fields[2].text == "d");
  CHECK(r.line == 1);
  CHECK_FALSE(r.open_quote);
  r = records.next();
  CHECK(r.line == 3);
  CHECK(r.fields.size() == 2);
  CHECK_FALSE(r.open_quote);
  r = records.next();
  CHECK(r.line == 4);
  CHECK(r.open_quote == std::pair{4, 1});
  CHECK(records.done());
}

TEST_CASE("read_text: a file past its limits is refused as the bytes that break them arrive") {
  const test_cli::TempDir dir("read_text");
  std::filesystem::create_directories(dir.path);
  const std::string file = (dir.path / "t").string();
  const auto error = [&](const std::string &text, const common::InputLimits &limits) {
    common::write_file_atomically(file, text);
    try {
      return common::read_text(file, "T", limits) == text ? std::string("(read)") : std::string("(other)");
    } catch (const common::InputError &e) {
      return e.diagnostic().substr(file.size());
    }
  };
  CHECK(error("ab\ncd\n", {6, 2}) == "(read)");
  CHECK(error("ab\ncd\ne", {6, 2}) == ": error: not a T file: more than 6 bytes");
  CHECK(error("ab\ncde\n", {100, 2}) == ":2: error: not a T file: line 2 is longer than 2 bytes");
  CHECK(error(std::string("ab\nc\0d\n", 7), {100}) == ":2:2: error: not a T file: a NUL byte");
  CHECK(error(std::string("ab\nc\0d\n", 7), {100, 100, false}) == "(read)");
  CHECK(common::size_text(common::kMiB) == "1 MiB");
  CHECK(common::size_text(1024 * common::kMiB) == "1 GiB");
}
