// The one batch row (app/batch/batch_row.hpp): a maze run's, a room run's and an mms run's rows
// in the same columns, joined by batch merge whatever their kinds, with totals a line a kind;
// an arena in a batch runs as a room run; older parts still read.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "app/batch/batch.hpp"
#include "cli_runner.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace {

namespace fs = std::filesystem;

// The rows batch merge reads from these parts' texts, written to a scratch folder.
std::vector<app::BatchRow> merge_parts(const test_cli::TempDir &dir, const std::vector<std::string> &texts) {
  fs::create_directories(dir.path);
  std::vector<std::string> files;
  for (std::size_t i = 0; i < texts.size(); ++i) {
    files.push_back((dir.path / fmt::format("part-{}.csv", i + 1)).string());
    common::write_file_atomically(files.back(), texts[i]);
  }
  return app::read_batch_csvs(files);
}

std::string totals_of(const std::vector<app::BatchRow> &rows) {
  app::BatchTotals totals;
  for (const app::BatchRow &row : rows) app::add_to_totals(totals, row);
  return app::format_totals(totals);
}

const std::string kRowHeader =
    "world,kind,robot,model,strategy,seed,size,end,end_message,steps,moves,sim_time_s,wall_time_ms,coverage,"
    "wall_accuracy,cell_accuracy,goal,speed_run,score,error";

}  // namespace

TEST_CASE("batch row: the columns are summary.json's core keys, then each kind's scores") {
  CHECK(app::batch_csv_header() == kRowHeader);
  app::BatchRow row;
  row.world = "a,b.txt";
  row.kind = app::RunKind::room;
  row.ran = true;
  row.robot = "ir-fan";
  row.model = "pie";
  row.strategy = "frontier";
  row.seed = 42;
  row.end = "done";
  row.end_message = "no frontier left";
  row.steps = 2464;
  row.sim_time_s = 78.848;
  row.wall_time_ms = 2994.4;
  row.coverage_percent = 100.0;
  row.cell_accuracy_percent = 86.466;
  CHECK(app::format_batch_csv_row(row) ==
        "\"a,b.txt\",room,ir-fan,pie,frontier,42,,done,no frontier left,2464,,78.848,2994,100.00,,86.47,,,,\n");
  app::BatchRow not_run;
  not_run.world = "gone.room";
  not_run.kind = app::RunKind::room;
  not_run.error = "error: cannot read gone.room";
  CHECK(app::format_batch_csv_row(not_run) == "gone.room,room,,,,,,,,,,,,,,,,,,error: cannot read gone.room\n");
}

TEST_CASE("batch merge: maze, room and mms parts join into one CSV; the totals are a line a kind") {
  const test_cli::TempDir dir("merge_kinds");
  const std::string maze_part = kRowHeader + "\n" +
                                "a.txt,maze,hambot,cell,dfs,42,4x4,done,,2000,29,60.000,3,100.00,100.00,,,,,\n"
                                "b.txt,maze,hambot,cell,dfs,42,4x4,incomplete,3 cells,900,12,30.000,2,50.00,75.00,,,,,"
                                "ended: incomplete (3 cells)\n";
  const std::string room_part = kRowHeader + "\n" +
                                "r.room,room,ir-fan,pie,frontier,42,,done,,2464,,78.848,2994,100.00,,86.47,,,,\n"
                                "s.room,room,,,,,,,,,,,,,,,,,,error: cannot read s.room\n";
  const std::string mms_part = kRowHeader + "\n" +
                               "m.txt,mms,hambot,cell,python3 f.py,42,4x4,exited,,700,20,20.000,5,100.00,100.00,,"
                               "reached,,1200,\n";
  const std::vector<app::BatchRow> rows = merge_parts(dir, {maze_part, room_part, mms_part});
  REQUIRE(rows.size() == 5);
  CHECK(rows[0].kind == app::RunKind::maze);
  CHECK(rows[0].ok);
  CHECK_FALSE(rows[1].ok);
  CHECK(rows[2].kind == app::RunKind::room);
  CHECK(rows[2].ok);
  CHECK(rows[2].cell_accuracy_percent == doctest::Approx(86.47));
  CHECK_FALSE(rows[2].wall_accuracy_percent);
  CHECK_FALSE(rows[3].ran);
  CHECK(rows[4].kind == app::RunKind::mms);
  CHECK(rows[4].ok);
  CHECK(rows[4].score == doctest::Approx(1200.0));
  // Joined, each row is written back as it was read.
  std::string joined;
  for (const app::BatchRow &row : rows) joined += app::format_batch_csv_row(row);
  CHECK(kRowHeader + "\n" + joined ==
        maze_part + room_part.substr(kRowHeader.size() + 1) + mms_part.substr(kRowHeader.size() + 1));
  CHECK(totals_of(rows) ==
        "total maze: 2 worlds, 1 ok, 1 failed; moves 41; mean coverage 75.00%; mean wall_accuracy 87.50%; run time 5 ms\n"
        "total room: 2 worlds, 1 ok, 1 failed; mean coverage 100.00%; mean cell_accuracy 86.47%; run time 2994 ms\n"
        "total mms: 1 worlds, 1 ok, 0 failed; moves 20; mean coverage 100.00%; mean wall_accuracy 100.00%; goal "
        "reached 1 of 1; mean score 1200; run time 5 ms\n"
        "total: 5 worlds, 3 ok, 2 failed; run time 3004 ms");
}

TEST_CASE("batch merge: a room row that ended incomplete, or an mms row that missed its goal, is failed") {
  const test_cli::TempDir dir("merge_kind_ends");
  const std::vector<app::BatchRow> rows =
      merge_parts(dir, {kRowHeader + "\n" + "r.room,room,ir-fan,pie,frontier,42,,incomplete,,10,,1.000,3,50.00,,80.00,,,,\n" +
                   "t.room,room,ir-fan,pie,wander,42,,time limit,,10,,1.000,3,50.00,,80.00,,,,\n" +
                   "m.txt,mms,hambot,cell,f,42,4x4,exited,,7,2,1.000,5,10.00,90.00,,not reached,,0,\n"});
  REQUIRE(rows.size() == 3);
  CHECK_FALSE(rows[0].ok);
  CHECK(rows[1].ok);  // a room run's time limit is its planned end
  CHECK_FALSE(rows[2].ok);
}

TEST_CASE("batch merge: parts of the older maze and mms batches read as those kinds' rows") {
  const test_cli::TempDir dir("merge_older");
  const std::string maze_part = "world,size,moves,coverage,wall_accuracy,goal,speed_run,ms,end,error\n"
                                "a.txt,4x4,29,100.00,97.50,reached,14,3,done,\n"
                                "b.num,,,,,,,,,error: no goal\n";
  const std::string mms_part =
      "world,size,end,lines,moves,goal,total_distance,total_turns,total_effective_distance,best_run_distance,"
      "best_run_turns,best_run_effective_distance,score,ms,error\n"
      "m.txt,4x4,exited,40,20,reached,20,9,14.5,6,3,4.5,130.5,8,\n"
      "n.txt,,failed,,,,,,,,,,,,\"error: cannot read n.txt\"\n";
  const std::vector<app::BatchRow> rows = merge_parts(dir, {maze_part, mms_part});
  REQUIRE(rows.size() == 4);
  CHECK(app::format_batch_csv_row(rows[0]) == "a.txt,maze,,,,,4x4,done,,,29,,3,100.00,97.50,,reached,14,,\n");
  CHECK(rows[0].ok);
  CHECK_FALSE(rows[1].ran);
  CHECK(app::format_batch_csv_row(rows[2]) == "m.txt,mms,,,,,4x4,exited,,,20,,8,,,,reached,,130.5,\n");
  CHECK(rows[2].ok);
  CHECK_FALSE(rows[3].ran);
  CHECK(rows[3].end.empty());
  CHECK(rows[3].kind == app::RunKind::mms);
}

TEST_CASE("batch merge: a header that is none of the batches' names the one to write") {
  const test_cli::TempDir dir("merge_header");
  fs::create_directories(dir.path);
  const std::string file = (dir.path / "x.csv").string();
  common::write_file_atomically(file, "world,size\na,4x4\n");
  CHECK_THROWS_WITH_AS(app::read_batch_csvs({file}),
                       fmt::format("not a batch CSV (the first line must be '{}')", kRowHeader).c_str(),
                       common::InputError);
}

TEST_CASE("batch: a folder's arenas run as room runs, their rows the room's scores; --kind maze skips them") {
  const test_cli::TempDir dir("batch_room");
  fs::create_directories(dir.path);
  fs::copy_file(std::string(WORLDS_DIR) + "/ir_room.room", dir.path / "ir_room.room");
  fs::copy_file(std::string(WORLDS_DIR) + "/lab4x4.txt", dir.path / "lab4x4.txt");
  const std::string room = (dir.path / "ir_room.room").string();
  const std::string lab = (dir.path / "lab4x4.txt").string();

  const app::WorldList mazes = app::expand_worlds({dir.path.string()}, app::KindChoice::maze);
  CHECK(mazes.worlds == std::vector<std::string>{lab});
  CHECK(mazes.skipped == std::vector<std::string>{room});
  const app::WorldList all = app::expand_worlds({dir.path.string()}, app::KindChoice::automatic);
  CHECK(all.worlds == std::vector<std::string>{room, lab});
  CHECK(all.skipped_as == "not worlds");
  const std::vector<app::BatchJob> jobs = app::plain_jobs(all.worlds, app::KindChoice::automatic);
  REQUIRE(jobs.size() == 2);
  CHECK(jobs[0].kind == app::RunKind::room);
  CHECK(jobs[1].kind == app::RunKind::maze);
  CHECK(app::plain_jobs({lab}, app::KindChoice::room)[0].kind == app::RunKind::room);

  app::RunOptions options;
  options.output.quiet = true;
  options.max_steps = 300;  // the room run stops early: its row still has its scores
  const std::vector<app::BatchItem> items = app::run_batch(options, jobs, 2, {});
  REQUIRE(items.size() == 2);
  const app::BatchRow row = app::row_of(items[0]);
  CHECK(row.kind == app::RunKind::room);
  CHECK(row.ran);
  CHECK(row.robot == "hambot");
  CHECK(row.model == "ray");
  CHECK(row.strategy == "frontier");
  CHECK(row.steps == 300);
  CHECK(row.end == "max steps");
  CHECK(row.error == "ended: max steps (the step limit was reached)");
  CHECK(row.cell_accuracy_percent.has_value());
  CHECK(row.coverage_percent.has_value());
  CHECK_FALSE(row.wall_accuracy_percent);
  CHECK(row.size.empty());
  CHECK(app::row_of(items[1]).kind == app::RunKind::maze);
  const std::string table = app::format_batch_table(items, 1.0, all.skipped, all.skipped_as);
  CHECK(table.find("cell_accuracy") != std::string::npos);
  CHECK(table.find("total room: 1 worlds, 0 ok, 1 failed; mean coverage") != std::string::npos);

  // The batch's CSV merges back to the same rows.
  const std::string csv = app::format_batch_csv(items);
  const std::vector<app::BatchRow> rows = merge_parts(dir, {csv});
  REQUIRE(rows.size() == 2);
  CHECK(app::format_batch_csv_row(rows[0]) == app::format_batch_csv_row(row));
  CHECK_FALSE(rows[0].ok);
}

TEST_CASE("batch: --strategy names a maze run's strategy, a room run's, or frontier for both") {
  const test_cli::TempDir dir("batch_strategy");
  fs::create_directories(dir.path);
  const std::string room = std::string(WORLDS_DIR) + "/ir_room.room";
  const std::string lab = std::string(WORLDS_DIR) + "/lab4x4.txt";
  const std::string csv = (dir.path / "rows.csv").string();
  const auto strategies = [&](const std::string &strategy) {
    test_cli::run({"batch", room, lab, "--strategy", strategy, "--max-steps", "3000", "--csv", csv});
    std::vector<std::string> names;
    for (const app::BatchRow &row : app::read_batch_csvs({csv})) names.push_back(row.strategy);
    return names;
  };
  CHECK(strategies("wavefront") == std::vector<std::string>{"wavefront", "dfs"});
  CHECK(strategies("floodfill") == std::vector<std::string>{"frontier", "floodfill"});
  CHECK(strategies("frontier") == std::vector<std::string>{"frontier", "frontier"});
  CHECK_THROWS_WITH_AS(test_cli::run({"batch", lab, "--strategy", "zigzag"}),
                       "unknown --strategy 'zigzag' (a maze run's dfs, frontier, left-wall, right-wall or floodfill; "
                       "a room run's waypoints, wavefront, frontier or wander)",
                       common::InputError);
  CHECK_THROWS_WITH_AS(test_cli::run({"batch", room, "--cells", "5,5", "--resolution", "0.1"}),
                       "give --cells or --resolution, not both", common::InputError);
}

TEST_CASE("batch: a room run keeps the room options the batch read, with the batch's shared ones") {
  app::RunOptions room_only = app::metres_run_options();
  room_only.strategy = explore::StrategyKind::waypoints;
  room_only.metres.controller.waypoints = {{1.0, 2.0}};
  room_only.metres.controller.laps = 2;
  room_only.metres.resolution_m = 0.2;
  app::RunOptions options;
  options.simulation.seed = 9;
  options.time_limit_s = 30.0;
  const app::RunOptions room = app::room_options_for(options, room_only, [](std::string_view) { return false; });
  CHECK(room.strategy == explore::StrategyKind::waypoints);
  CHECK(room.metres.controller.waypoints.size() == 1);
  CHECK(room.metres.controller.laps == 2);
  CHECK(room.metres.resolution_m == 0.2);
  CHECK(room.simulation.seed == 9);
  CHECK(room.time_limit_s == 30.0);
  CHECK(room.output.quiet);
  CHECK(room.model.kind == sensing::ModelKind::ray);
}

TEST_CASE("batch: a folder's world with 5 KB of comments before its first statement is run, as show reads it") {
  const test_cli::TempDir dir("batch_comments");
  fs::create_directories(dir.path);
  std::string text;
  while (text.size() < 5000) text += "# a comment before the room's first statement\n";
  const std::string room = (dir.path / "commented.room").string();
  common::write_file_atomically(room, text + "boundary 0 5 0 3\nstart 0.5 0.5 0\ngoal 4 2\n");
  const app::WorldList all = app::expand_worlds({dir.path.string()}, app::KindChoice::automatic);
  CHECK(all.worlds == std::vector<std::string>{room});
  CHECK(all.skipped.empty());
}

TEST_CASE("batch merge: a quote never closed is refused at the line and column where it opened") {
  const test_cli::TempDir dir("merge_quote");
  std::string part = kRowHeader + "\n";
  const std::string row = "a.txt,maze,,,,,4x4,done,,10,9,,3,100.00,,,,,,\n";
  part += row + row + "\"b.txt,maze,,,,,4x4,done,,10,9,,3,100.00,,,,,,\n";
  for (int n = 0; n < 2000; ++n) part += row;  // the record runs on to the end of the text, once
  CHECK_THROWS_WITH_AS(merge_parts(dir, {part}),
                       "not a batch CSV row: the quoted field that opens here is never closed", common::InputError);
  try {
    app::read_batch_csv_text("p.csv", part);
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic() == "p.csv:4:1: error: not a batch CSV row: the quoted field that opens here is never closed");
  }
}

TEST_CASE("batch merge: a part of NUL bytes is refused at its first byte, not read whole") {
  const test_cli::TempDir dir("merge_nul");
  try {
    merge_parts(dir, {std::string(300'000, '\0')});
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic().ends_with("part-1.csv:1:1: error: not a batch CSV file: a NUL byte"));
  }
}
