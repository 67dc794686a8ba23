// Telling a world file's format (maze/world/format_detector.hpp): by its first meaningful
// line, whatever comes before it and however its bytes arrive, and refused early when no
// such line comes.
#include <doctest/doctest.h>

#include <unistd.h>

#include <chrono>
#include <optional>
#include <string>
#include <thread>

#include "cli_runner.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "maze/world/format_detector.hpp"
#include "maze/world/world_files.hpp"

namespace {

const std::string kRoomBody = "boundary 0 5 0 3\nrect 1 1 2 2\nstart 0.5 0.5 0\ngoal 4 2\n";

// 70 KB of comment lines, more than one read's 64 KiB.
std::string long_comments() {
  std::string text;
  while (text.size() < 70'000) text += "# a comment line of the room, one of many before its first statement\n";
  return text;
}

// The diagnostic read_world_file gives for `text` written to a file, or "(no error)".
std::string read_error(const test_cli::TempDir &dir, const std::string &text) {
  std::filesystem::create_directories(dir.path);
  const std::string file = (dir.path / "w").string();
  common::write_file_atomically(file, text);
  try {
    maze::read_world_file(file);
  } catch (const common::InputError &e) {
    return e.diagnostic().substr(file.size());
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("format: a room file after 70 KB of comment lines reads as a room file") {
  const test_cli::TempDir dir("detect_comments");
  std::filesystem::create_directories(dir.path);
  const std::string file = (dir.path / "long.room").string();
  common::write_file_atomically(file, long_comments() + kRoomBody);
  CHECK(maze::read_world_file(file).format == maze::Format::room);
  CHECK(maze::read_world_format(file) == maze::Format::room);
}

TEST_CASE("format: a room file arriving through a pipe in pieces reads as the same file read at once") {
  for (const std::string &first : {std::string("# a comment\n"), std::string("\n\n  boun"), long_comments()}) {
    int ends[2];
    REQUIRE(::pipe(ends) == 0);
    const std::string whole = first + (first.ends_with("boun") ? "dary 0 5 0 3\n" : kRoomBody);
    std::thread writer([&] {
      CHECK(::write(ends[1], first.data(), first.size()) == static_cast<ssize_t>(first.size()));
      std::this_thread::sleep_for(std::chrono::milliseconds(150));
      const std::string rest = whole.substr(first.size());
      CHECK(::write(ends[1], rest.data(), rest.size()) == static_cast<ssize_t>(rest.size()));
      ::close(ends[1]);
    });
    maze::WorldText read;
    CHECK_NOTHROW(read = maze::read_world_file("/dev/fd/" + std::to_string(ends[0])));
    writer.join();
    ::close(ends[0]);
    CHECK(read.format == maze::Format::room);
    CHECK(read.text == whole);
  }
}

TEST_CASE("format: blank lines before a text world are no binary .maz") {
  const std::string blanks(200, '\n');
  CHECK(maze::detect_format(blanks + kRoomBody, "f") == maze::Format::room);
  CHECK(maze::detect_format(blanks + "<world/>\n", "f") == maze::Format::xml);
  CHECK(maze::detect_format(std::string(100, '\r') + blanks + "0 0 1 1 1 1\n", "f") == maze::Format::num);
  // A .maz's corner cell may well be a tab, a line feed or a carriage return's byte.
  CHECK(maze::detect_format(std::string("\x0D\x0A\x09\x0C") + std::string(252, '\x0A'), "m") == maze::Format::maz);
}

TEST_CASE("format: a file of blank lines is refused after the first 1 MiB, at the line the look stopped at") {
  const test_cli::TempDir dir("detect_blank");
  const std::string error = read_error(dir, std::string(std::size_t{3} << 20, '\n'));
  CHECK(error.starts_with(
      ":1048577:1: error: cannot tell the format: no line but blank and comment lines in the first 1 MiB; expected"));
  CHECK(read_error(dir, "\n\n# x\n  \t\n").starts_with(":1:1: error: cannot tell the format: expected"));
  CHECK(read_error(dir, "# x\n\n   bondary 0 5 0 3\n").starts_with(":3:4: error: cannot tell the format: expected"));
}

TEST_CASE("format: told the same whether the bytes come at once or one at a time") {
  for (const std::string &text : {kRoomBody, std::string("\xEF\xBB\xBF# c\n\nrect 0 0 1 1\n"), std::string("o---o\n"),
                                 std::string("\n \n<world/>"), std::string("\t\r\n\x0E\x0A")}) {
    const maze::Format at_once = maze::detect_format(text, "f");
    maze::FormatDetector detector("f");
    std::optional<maze::Format> told;
    for (std::size_t n = 1; n <= text.size() && !told; ++n) told = detector.look(text.substr(0, n), n == text.size());
    CHECK(told == at_once);
  }
}
