// batch --shard K/N and batch merge (app/batch/batch.hpp): the parts are disjoint and together the
// whole list, and the merged parts' CSV is a single run's, apart from the times.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/batch/batch.hpp"
#include "cli_runner.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> names(int n) {
  std::vector<std::string> list;
  for (int i = 1; i <= n; ++i) list.push_back(fmt::format("w{}", i));
  return list;
}

// The CSV without every row's wall_time_ms (the one column that differs between runs).
std::string without_times(std::vector<app::BatchRow> rows) {
  std::string csv;
  for (app::BatchRow &row : rows) {
    row.wall_time_ms.reset();
    csv += app::format_batch_csv_row(row);
  }
  return csv;
}

// A part: the header, then the rows.
std::string part(const std::string &rows) { return app::batch_csv_header() + "\n" + rows; }

// A maze row that ran: its moves, coverage, wall_accuracy and wall_time_ms cells as given.
std::string maze_row(const std::string &world, const std::string &moves, const std::string &coverage,
                     const std::string &wall_accuracy, const std::string &ms, const std::string &end = "done") {
  return fmt::format("{},maze,hambot,cell,dfs,42,4x4,{},,120,{},12.000,{},{},{},,,,,\n", world, end, moves, ms,
                     coverage, wall_accuracy);
}

}  // namespace

TEST_CASE("batch --shard: contiguous parts, disjoint, together the list in order") {
  using L = std::vector<std::string>;
  CHECK(app::shard_of(names(7), {1, 3}) == L{"w1", "w2"});
  CHECK(app::shard_of(names(7), {2, 3}) == L{"w3", "w4"});
  CHECK(app::shard_of(names(7), {3, 3}) == L{"w5", "w6", "w7"});
  CHECK(app::shard_of(names(2), {1, 4}) == L{});
  CHECK(app::shard_of(names(2), {2, 4}) == L{"w1"});
  for (const int n : {1, 2, 5, 16}) {
    for (const int count : {1, 2, 3, 7, 20}) {
      L joined;
      for (int k = 1; k <= count; ++k) {
        for (const std::string &w : app::shard_of(names(n), {k, count})) joined.push_back(w);
      }
      CHECK(joined == names(n));
    }
  }
  CHECK(app::parse_shard("2/8").index == 2);
  CHECK(app::parse_shard("2/8").count == 8);
  for (const char *bad : {"0/2", "3/2", "1", "a/b", "1/0", "/", "1/2/3"}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(app::parse_shard(bad), common::InputError);
  }
}

TEST_CASE("batch merge: three parts of worlds/ with floodfill and a speed run equal one run's CSV") {
  app::RunOptions options;
  options.strategy = explore::StrategyKind::floodfill;
  options.plan.speed_run = true;
  options.output.quiet = true;
  const app::WorldList list = app::expand_worlds({WORLDS_DIR});
  const std::vector<app::BatchItem> whole = app::run_batch(options, list.worlds, 2, {});
  const fs::path dir = fs::temp_directory_path() / fmt::format("maze_mapper_shard_{}", ::getpid());
  fs::create_directories(dir);
  std::vector<std::string> parts;
  for (int k = 1; k <= 3; ++k) {
    const std::vector<std::string> worlds = app::shard_of(list.worlds, {k, 3});
    parts.push_back((dir / fmt::format("part-{}.csv", k)).string());
    common::write_file_atomically(parts.back(), app::format_batch_csv(app::run_batch(options, worlds, 1, {})));
  }
  const std::vector<app::BatchRow> merged = app::read_batch_csvs(parts);
  const std::string single = (dir / "single.csv").string();
  common::write_file_atomically(single, app::format_batch_csv(whole));
  const std::vector<app::BatchRow> one_run = app::read_batch_csvs({single});
  fs::remove_all(dir);
  REQUIRE(merged.size() == list.worlds.size());
  CHECK(without_times(merged) == without_times(one_run));
  // The columns say what the runs did: a num world has no goal (a failed row); the text
  // worlds' goals are reached and their speed runs made.
  app::BatchTotals totals;
  for (const app::BatchRow &row : merged) {
    CAPTURE(row.world);
    app::add_to_totals(totals, row);
    if (row.world.ends_with("lab4x4.num")) {
      CHECK_FALSE(row.ran);
      CHECK(row.error.find("--strategy floodfill needs a goal cell") != std::string::npos);
    }
    if (row.world.ends_with("lab4x4.txt")) {
      CHECK(row.goal == "reached");
      CHECK(row.speed_run == "14");
    }
  }
  const app::KindTotals &mazes = totals.of(app::RunKind::maze);
  CHECK(mazes.worlds == static_cast<int>(list.worlds.size()));
  CHECK(mazes.with_goal == mazes.goal_reached);
}

TEST_CASE("batch merge: a file that is no batch CSV says where") {
  const fs::path file = fs::temp_directory_path() / fmt::format("maze_mapper_merge_{}.csv", ::getpid());
  common::write_file_atomically(file.string(), part("\"a\",maze,hambot,cell,dfs,42,4x4,done,,120,x,12.000,1,100.00,100.00,,,,,\"\"\n"));
  std::string diagnostic;
  try {
    app::read_batch_csvs({file.string()});
  } catch (const common::InputError &e) {
    diagnostic = e.diagnostic();
  }
  CHECK(diagnostic == fmt::format("{}:2:43: error: moves must be a whole number from 0 (got 'x')", file.string()));
  fs::remove(file);
}

namespace {

// The diagnostic read_batch_csvs throws for these parts, or "" when they merge.
std::string merge_error(const std::vector<std::string> &parts) {
  try {
    app::read_batch_csvs(parts);
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "";
}

}  // namespace

TEST_CASE("batch merge: a part saved with a byte order mark and CRLF line ends reads as the plain one") {
  const test_cli::TempDir dir("merge_crlf");
  fs::create_directories(dir.path);
  const std::string rows = maze_row("\"a.txt\"", "29", "100.00", "97.50", "3") + maze_row("\"b\nc.txt\"", "12", "50.00", "75.00", "4");
  const std::string plain = (dir.path / "plain.csv").string();
  const std::string windows = (dir.path / "windows.csv").string();
  common::write_file_atomically(plain, part(rows));
  std::string crlf = "\xEF\xBB\xBF" + part(rows);
  for (std::size_t at = crlf.find('\n'); at != std::string::npos; at = crlf.find('\n', at + 2)) crlf.insert(at, "\r");
  common::write_file_atomically(windows, crlf);
  const std::vector<app::BatchRow> want = app::read_batch_csvs({plain});
  const std::vector<app::BatchRow> got = app::read_batch_csvs({windows});
  REQUIRE(got.size() == 2);
  CHECK(got[1].world == "b\nc.txt");
  CHECK(without_times(got) == without_times(want));
}

TEST_CASE("batch merge: a part given twice is refused, by its real path or its rows; empty parts may repeat") {
  const test_cli::TempDir dir("merge_twice");
  fs::create_directories(dir.path);
  const std::string a = (dir.path / "a.csv").string();
  const std::string copy = (dir.path / "copy.csv").string();
  const std::string link = (dir.path / "link.csv").string();
  const std::string empty1 = (dir.path / "empty1.csv").string();
  const std::string empty2 = (dir.path / "empty2.csv").string();
  common::write_file_atomically(a, part(maze_row("a.txt", "29", "100.00", "97.50", "3")));
  common::write_file_atomically(copy, part(maze_row("a.txt", "29", "100.00", "97.50", "3")));
  common::write_file_atomically(empty1, part(""));
  common::write_file_atomically(empty2, part(""));
  fs::create_symlink(a, link);
  CHECK(merge_error({a, a}) == fmt::format("{}: error: is {} again (the same file): its rows would count twice", a, a));
  CHECK(merge_error({a, link}) ==
        fmt::format("{}: error: is {} again (the same file): its rows would count twice", link, a));
  CHECK(merge_error({a, copy}) == fmt::format("{}: error: holds the same rows as {}: its rows would count twice", copy, a));
  CHECK(merge_error({empty1, a, empty2}).empty());
}

TEST_CASE("batch merge: a number out of its column's range says where, to the column") {
  const test_cli::TempDir dir("merge_range");
  fs::create_directories(dir.path);
  const std::string file = (dir.path / "part.csv").string();
  const auto error_for = [&](const std::string &row) {
    common::write_file_atomically(file, part(row));
    return merge_error({file});
  };
  CHECK(error_for(maze_row("a.txt", "29", "250", "97.50", "3")) ==
        file + ":2:57: error: coverage must be a percentage from 0 to 100 (got '250')");
  CHECK(error_for(maze_row("a.txt", "29", "100", "-1", "3")) ==
        file + ":2:61: error: wall_accuracy must be a percentage from 0 to 100 (got '-1')");
  CHECK(error_for(maze_row("a.txt", "-3", "100", "100", "3")) ==
        file + ":2:45: error: moves must be a whole number from 0 (got '-3')");
  CHECK(error_for(maze_row("a.txt", "3", "100", "100", "inf")) ==
        file + ":2:54: error: wall_time_ms must be a number of milliseconds from 0 (got 'inf')");
  CHECK(error_for("a.txt,room,ir-fan,pie,frontier,42,,done,,120,,12.000,3,100,,101,,,,\n") ==
        file + ":2:61: error: cell_accuracy must be a percentage from 0 to 100 (got '101')");
  CHECK(error_for("a.txt,rooms,ir-fan,pie,frontier,42,,done,,120,,12.000,3,100,,99,,,,\n") ==
        file + ":2:7: error: kind must be maze, room or mms (got 'rooms')");
  CHECK(error_for(maze_row("a.txt", "3", "100", "100", "0")).empty());
}

TEST_CASE("batch merge: a row that ended incomplete, wrong or without progress is failed in the merged totals") {
  const fs::path file = fs::temp_directory_path() / fmt::format("maze_mapper_merge_ends_{}.csv", ::getpid());
  std::string text;
  for (const char *end : {"done", "wrong map", "incomplete", "no progress"}) {
    text += maze_row(fmt::format("\"{}.txt\"", end), "29", "100.00", "97.50", "3", end);
  }
  common::write_file_atomically(file.string(), part(text));
  const std::vector<app::BatchRow> rows = app::read_batch_csvs({file.string()});
  REQUIRE(rows.size() == 4);
  CHECK(rows[0].ok);
  CHECK_FALSE(rows[1].ok);
  CHECK_FALSE(rows[2].ok);
  CHECK_FALSE(rows[3].ok);
  fs::remove(file);
}

TEST_CASE("batch --each-start: a row per start position, each run from its own start") {
  const std::string arena = std::string(TEST_DATA_DIR) + "/worlds/course_arena5_starts.xml";
  const std::string lab = std::string(WORLDS_DIR) + "/lab4x4.txt";
  const std::string missing = std::string(WORLDS_DIR) + "/no-such-world.txt";
  const std::vector<app::BatchJob> jobs = app::each_start_jobs({arena, lab, missing}, {});
  REQUIRE(jobs.size() == 27);
  CHECK(app::job_name(jobs[0]) == arena + " pos:1");
  CHECK(app::job_name(jobs[24]) == arena + " pos:25");
  CHECK(app::job_name(jobs[25]) == lab + " pos:1");
  CHECK(app::job_name(jobs[26]) == missing);  // its row says why it did not run
  app::RunOptions options;
  options.output.quiet = true;
  const std::vector<app::BatchJob> some{jobs[0], jobs[2], jobs[26]};
  const std::vector<app::BatchItem> items = app::run_batch(options, some, 1, {});
  REQUIRE(items.size() == 3);
  CHECK(items[0].ok);
  CHECK(items[1].ok);
  CHECK(items[0].world == arena + " pos:1");
  // pos:1 and pos:3 start in different cells, so their searches differ.
  CHECK(items[0].summary.moves != items[1].summary.moves);
  CHECK_FALSE(items[2].ran);
  CHECK(items[2].bad_input);
}
