// common::write_file_atomically and OutputFile: what each kind of target becomes (a regular
// file replaced whole, a link followed, a device or FIFO written in place), a write that
// fails leaves nothing, an output that is an input is refused, a full device says so.
#include <doctest/doctest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace {

namespace fs = std::filesystem;

struct Scratch {
  fs::path dir;
  Scratch() {
    char name[] = "/tmp/maze_mapper_atomic_XXXXXX";
    dir = ::mkdtemp(name);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  std::string operator/(const std::string &name) const { return (dir / name).string(); }
  // The entries of the directory, temporaries included.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const fs::directory_entry &e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    return names;
  }
};

std::string read(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("a new or regular file is replaced whole through a temporary that does not stay") {
  const Scratch s;
  common::write_file_atomically(s / "a.txt", "one\n");
  CHECK(read(s / "a.txt") == "one\n");
  common::write_file_atomically(s / "a.txt", "two\n");
  CHECK(read(s / "a.txt") == "two\n");
  CHECK(s.entries() == std::vector<std::string>{"a.txt"});
}

TEST_CASE("a symbolic link stays a link; its final target (through a link of a link) gets the content") {
  const Scratch s;
  common::write_file_atomically(s / "target.txt", "old\n");
  fs::create_symlink("target.txt", s / "link1.txt");
  fs::create_symlink(s / "link1.txt", s / "link2.txt");
  common::write_file_atomically(s / "link2.txt", "new\n");
  CHECK(fs::is_symlink(fs::symlink_status(s / "link1.txt")));
  CHECK(fs::is_symlink(fs::symlink_status(s / "link2.txt")));
  CHECK(read(s / "target.txt") == "new\n");
  SUBCASE("a dangling link names the file to create") {
    fs::create_symlink("made.txt", s / "dangling.txt");
    common::write_file_atomically(s / "dangling.txt", "made\n");
    CHECK(fs::is_symlink(fs::symlink_status(s / "dangling.txt")));
    CHECK(read(s / "made.txt") == "made\n");
  }
  SUBCASE("a loop of links is an error") {
    fs::create_symlink("loop_b", s / "loop_a");
    fs::create_symlink("loop_a", s / "loop_b");
    CHECK_THROWS_WITH_AS(common::write_file_atomically(s / "loop_a", "x"),
                         ("cannot write " + (s / "loop_a") + ": Too many levels of symbolic links").c_str(),
                         common::InputError);
  }
}

TEST_CASE("a character device is written in place, never replaced") {
  common::write_file_atomically("/dev/null", "gone\n");
  struct stat st {};
  REQUIRE(::stat("/dev/null", &st) == 0);
  CHECK(S_ISCHR(st.st_mode));
  CHECK(common::resolve_write_target("/dev/null").kind == common::WriteTarget::Kind::direct);
}

TEST_CASE("a FIFO stays a FIFO and its reader gets the content") {
  const Scratch s;
  const std::string fifo = s / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string got;
  std::thread reader([&got, &fifo] { got = read(fifo); });
  common::write_file_atomically(fifo, "through the pipe\n");
  reader.join();
  CHECK(got == "through the pipe\n");
  struct stat st {};
  REQUIRE(::lstat(fifo.c_str(), &st) == 0);
  CHECK(S_ISFIFO(st.st_mode));
  CHECK(s.entries() == std::vector<std::string>{"pipe"});
}

TEST_CASE("an OutputFile not committed leaves no temporary and the old file as it was") {
  const Scratch s;
  common::write_file_atomically(s / "trace.csv", "old\n");
  {
    common::OutputFile file(s / "trace.csv");
    file.write("half of a new");
    CHECK(s.entries().size() == 2);  // the temporary beside it
  }
  CHECK(s.entries() == std::vector<std::string>{"trace.csv"});
  CHECK(read(s / "trace.csv") == "old\n");
  common::OutputFile file(s / "trace.csv");
  for (int i = 0; i < 100000; ++i) file.write("0123456789abcdef\n");  // past the 1 MiB buffer
  file.commit();
  CHECK(fs::file_size(s / "trace.csv") == 1700000);
}

TEST_CASE("a directory, a missing folder and a full device are errors that leave nothing") {
  const Scratch s;
  CHECK_THROWS_WITH_AS(common::write_file_atomically(s.dir.string(), "x"),
                       ("cannot write " + s.dir.string() + ": Is a directory").c_str(), common::InputError);
  CHECK_THROWS_WITH_AS(common::write_file_atomically(s / "no/such.txt", "x"),
                       ("cannot write " + (s / "no/such.txt") + ": No such file or directory").c_str(),
                       common::InputError);
  CHECK_THROWS_WITH_AS(common::write_file_atomically("/dev/full", "x"),
                       "cannot write /dev/full: No space left on device", common::NoSpaceError);
  CHECK(s.entries().empty());
}

TEST_CASE("an output that is one of the inputs is refused, through links too") {
  const Scratch s;
  common::write_file_atomically(s / "a.txt", "maze\n");
  fs::create_symlink("a.txt", s / "alias.txt");
  CHECK_THROWS_WITH_AS(common::refuse_output_over_input("--csv", s / "a.txt", {s / "b.txt", s / "a.txt"}),
                       ("--csv " + (s / "a.txt") + " is also an input: refusing to overwrite it").c_str(),
                       common::InputError);
  CHECK_THROWS_WITH_AS(common::refuse_output_over_input("--csv", s / "alias.txt", {s / "a.txt"}),
                       ("--csv " + (s / "alias.txt") + " is also an input (" + (s / "a.txt") +
                        "): refusing to overwrite it")
                           .c_str(),
                       common::InputError);
  CHECK_NOTHROW(common::refuse_output_over_input("--csv", s / "new.csv", {s / "a.txt"}));
  CHECK_NOTHROW(common::refuse_output_over_input("--csv", "/dev/null", {"/dev/null"}));
}

TEST_CASE("control bytes in a message are escaped, other bytes kept") {
  CHECK(common::printable("a\x1b[2Jb\nc\x7f") == "a\\x1b[2Jb\\x0ac\\x7f");
  CHECK(common::printable("caf\xc3\xa9") == "caf\xc3\xa9");
  CHECK(common::InputError("bad \x1b").diagnostic() == "error: bad \\x1b");
}
