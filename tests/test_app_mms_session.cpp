// mms-protocol algorithms driving the simulated robot: the README's conversation in both
// wall modes, and tiny scripts that misbehave on purpose (hang, crash, garbage, flood, give
// up): each ends the run with its reason, and no child is left behind.

#include <doctest/doctest.h>

#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "app/batch/batch.hpp"
#include "app/batch/mms_batch.hpp"
#include "app/mms/mms_session.hpp"
#include "cli_runner.hpp"
#include "common/atomic_file.hpp"
#include "common/deadline.hpp"
#include "common/error.hpp"
#include "maze/sim/profile.hpp"

namespace {

namespace fs = std::filesystem;

const std::string kScripts = std::string(TEST_DATA_DIR) + "/mms/";

app::MmsRun run_script(const std::string &world, const std::string &script, app::MmsWalls walls,
                       double wall_limit_s = 20.0) {
  app::RunOptions options;
  options.world = std::string(WORLDS_DIR) + "/" + world;
  options.output.quiet = true;
  app::MmsOptions mms;
  mms.command = {"sh", kScripts + script};
  mms.walls = walls;
  mms.wall_limit_s = wall_limit_s;
  std::ostringstream out;
  return app::run_mms_world(options, mms, out);
}

// Whether a process runs (a zombie waiting for its new parent to reap it does not).
bool running(const std::string &pid) {
  std::ifstream stat("/proc/" + pid + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return false;
  const std::size_t after_name = line.rfind(')');
  return after_name != std::string::npos && line.size() > after_name + 2 && line[after_name + 2] != 'Z';
}

}  // namespace

TEST_CASE("mms: the README's example conversation runs unchanged, answers checked, in both wall modes") {
  for (const app::MmsWalls walls : {app::MmsWalls::truth, app::MmsWalls::sensed}) {
    const app::MmsRun run = run_script("classic16x16.txt", "readme_conversation.sh", walls);
    INFO(run.mms.message);
    CHECK(run.mms.end == app::MmsEnd::exited);
    CHECK(run.mms.lines == 18);
    CHECK(run.mms.crashes == 1);
    CHECK(run.summary.moves == 1);  // one cell north (ackReset's drive back is no move of the algorithm)
    CHECK(run.mms.stats.total_distance() == 1);
    CHECK(run.mms.stats.total_turns() == 1);
    CHECK(run.mms.marks.walls[0] == 8);  // setWall 0 0 W
    CHECK(run.mms.marks.texts[16].empty());  // set, then cleared
  }
}

TEST_CASE("mms: a wall limit past what the clock counts (1e10 s, inf) is no limit, not an end at once") {
  for (const double limit_s : {9.3e9, 1e10, 1e300, std::numeric_limits<double>::infinity()}) {
    INFO(limit_s);
    const app::MmsRun run = run_script("classic16x16.txt", "readme_conversation.sh", app::MmsWalls::truth, limit_s);
    CHECK(run.mms.end == app::MmsEnd::exited);
    CHECK(run.mms.lines == 18);
  }
  using Clock = std::chrono::steady_clock;
  const Clock::time_point now = Clock::now();
  CHECK(common::deadline_after<Clock>(now, 1e10) == Clock::time_point::max());
  CHECK(common::deadline_after<Clock>(now, 2.5) - now == std::chrono::milliseconds(2500));
}

TEST_CASE("mms: counts past what mms carries out crash, walls stop at the maze's edge, distances never wrap") {
  for (const app::MmsWalls walls : {app::MmsWalls::truth, app::MmsWalls::sensed}) {
    const app::MmsRun run = run_script("open_room6x6.txt", "huge_counts.sh", walls);
    INFO(run.mms.message);
    CHECK(run.mms.end == app::MmsEnd::exited);
    CHECK(run.mms.crashes == 5);
    CHECK(run.mms.stats.total_distance() == 2LL * app::kMaxMoveCells);
    CHECK(run.summary.moves == 10);  // five cells north and five back
  }
}

TEST_CASE("mms: --ignore-invalid skips getStat of a stat mms does not have, as mms drops it") {
  app::RunOptions options;
  options.world = std::string(WORLDS_DIR) + "/lab4x4.txt";
  options.output.quiet = true;
  app::MmsOptions mms;
  mms.command = {"sh", kScripts + "unknown_stat.sh"};
  mms.walls = app::MmsWalls::truth;
  std::ostringstream out;
  const app::MmsRun strict = app::run_mms_world(options, mms, out);
  CHECK(strict.mms.end == app::MmsEnd::protocol_error);
  CHECK(strict.mms.message == "line 1 \"getStat foo\": getStat: no stat 'foo'");
  mms.ignore_invalid = true;
  const app::MmsRun lenient = app::run_mms_world(options, mms, out);
  INFO(lenient.mms.message);
  CHECK(lenient.mms.end == app::MmsEnd::exited);
  CHECK(lenient.mms.lines == 2);
}

TEST_CASE("mms: --until goal ends an algorithm that never exits, once it stands in the centre") {
  app::RunOptions options;
  options.world = std::string(WORLDS_DIR) + "/open_room6x6.txt";
  options.output.quiet = true;
  app::MmsOptions mms;
  mms.command = {"sh", kScripts + "goal_then_loop.sh"};
  mms.until = app::MmsUntil::goal;
  std::ostringstream out;
  const app::MmsRun run = app::run_mms_world(options, mms, out);
  CHECK(run.mms.end == app::MmsEnd::reached);
  CHECK(run.summary.reached_goal);
  CHECK(run.mms.stats.best_run_distance() == 4);
  CHECK(run.mms.stats.best_run_turns() == 1);
  CHECK(run.mms.stats.score() == doctest::Approx(1 + 4 + 0.1 * (1 + 4)));
  CHECK(app::exit_status(run) == 0);
  CHECK(out.str().find("score: 5.5\n") != std::string::npos);
}

TEST_CASE("mms: misbehaving algorithms end the run with their reason, their process killed and reaped") {
  SUBCASE("hangs: the wall limit, its sleeping child killed too") {
    const std::string pid_file = fs::temp_directory_path() / fmt::format("mms_hang_{}.pid", ::getpid());
    ::setenv("MMS_TEST_PIDFILE", pid_file.c_str(), 1);
    const auto started = std::chrono::steady_clock::now();
    const app::MmsRun run = run_script("lab4x4.txt", "hang.sh", app::MmsWalls::truth, 1.0);
    ::unsetenv("MMS_TEST_PIDFILE");
    std::string sleeper;
    std::ifstream(pid_file) >> sleeper;
    fs::remove(pid_file);
    REQUIRE_FALSE(sleeper.empty());
    for (int i = 0; i < 100 && running(sleeper); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    CHECK_FALSE(running(sleeper));
    CHECK(run.mms.end == app::MmsEnd::wall_limit);
    CHECK(run.mms.message == "no end after 1 s (--wall-limit), 1 lines");
    CHECK(std::chrono::steady_clock::now() - started < std::chrono::seconds(10));
    REQUIRE(run.mms.exit);
    CHECK(run.mms.exit->signal == SIGKILL);
    CHECK(app::exit_status(run) == 1);
  }
  SUBCASE("exits, leaving a child in a session of its own that holds its output: its exit ends the run, the child killed") {
    const std::string pid_file = fs::temp_directory_path() / fmt::format("mms_escape_{}.pid", ::getpid());
    fs::remove(pid_file);
    ::setenv("MMS_TEST_PIDFILE", pid_file.c_str(), 1);
    const app::MmsRun run = run_script("lab4x4.txt", "escape.sh", app::MmsWalls::truth, 10.0);
    ::unsetenv("MMS_TEST_PIDFILE");
    std::string escaped;
    std::ifstream(pid_file) >> escaped;
    fs::remove(pid_file);
    REQUIRE_FALSE(escaped.empty());
    CHECK_FALSE(running(escaped));
    CHECK(run.mms.end == app::MmsEnd::exited);
    CHECK(run.mms.message == "the algorithm ended (exit status 0) after 0 lines");
  }
  SUBCASE("crashes") {
    const app::MmsRun run = run_script("lab4x4.txt", "crash.sh", app::MmsWalls::sensed);
    CHECK(run.mms.end == app::MmsEnd::failed);
    CHECK(run.mms.message == "the algorithm ended (killed by signal 11 (SIGSEGV)) after 1 lines");
  }
  SUBCASE("writes garbage: the line and its number") {
    const app::MmsRun run = run_script("lab4x4.txt", "garbage.sh", app::MmsWalls::truth);
    CHECK(run.mms.end == app::MmsEnd::protocol_error);
    CHECK(run.mms.message == "line 2 \"hello, simulator\": unknown command");
  }
  SUBCASE("floods one endless line") {
    const app::MmsRun run = run_script("lab4x4.txt", "flood.sh", app::MmsWalls::truth);
    CHECK(run.mms.end == app::MmsEnd::protocol_error);
    CHECK(run.mms.message == "line 1: longer than 4096 bytes (--max-line)");
  }
  SUBCASE("exits early") {
    const app::MmsRun run = run_script("lab4x4.txt", "early_exit.sh", app::MmsWalls::truth);
    CHECK(run.mms.end == app::MmsEnd::failed);
    CHECK(run.mms.message == "the algorithm ended (exit status 3) after 1 lines");
    CHECK_FALSE(run.summary.reached_goal);
    CHECK(run.mms.stats.score() == 2000.0F);
  }
}

TEST_CASE("mms: a command that cannot start is a bad input") {
  app::RunOptions options;
  options.world = std::string(WORLDS_DIR) + "/lab4x4.txt";
  app::MmsOptions mms;
  mms.command = {"/no/such/algorithm"};
  std::ostringstream out;
  CHECK_THROWS_WITH_AS(app::run_mms_world(options, mms, out), "cannot start '/no/such/algorithm': No such file or directory",
                       common::InputError);
}

TEST_CASE("mms batch: a row a maze; crashes, hangs, garbage and early exits fail their rows only") {
  app::RunOptions options;
  app::MmsOptions mms;
  mms.command = {"sh", kScripts + "by_size.sh"};
  mms.wall_limit_s = 2.0;
  const app::WorldList list = app::expand_worlds({WORLDS_DIR});
  const std::vector<app::MmsBatchItem> items = app::run_mms_batch(options, mms, list.worlds, 2, {}, nullptr);
  REQUIRE(items.size() == list.worlds.size());
  int ok = 0;
  for (const app::MmsBatchItem &item : items) {
    INFO(item.world << ": " << item.error);
    REQUIRE(item.ran);
    const int width = item.run.summary.width;
    const app::MmsEnd end = item.run.mms.end;
    if (width == 4) CHECK(item.error == "failed: the algorithm ended (killed by signal 11 (SIGSEGV)) after 1 lines");
    if (width == 8) CHECK(end == app::MmsEnd::wall_limit);
    if (width == 16) CHECK(item.error == "protocol error: line 2 \"garbage from a confused mouse\": unknown command");
    if (width == 32) CHECK(item.error == "failed: the algorithm ended (exit status 3) after 1 lines");
    if (width == 6) CHECK(item.ok);
    ok += item.ok ? 1 : 0;
  }
  CHECK(ok == 1);
  CHECK(app::mms_batch_exit_status(items) == 1);
  const std::string table = app::format_mms_batch_table(items, 0.0, list.skipped);
  CHECK(table.find("total: 9 worlds, 1 ok, 8 failed; goal reached 1 of 9") != std::string::npos);
  const std::string csv = app::format_mms_batch_csv(items);
  CHECK(csv.starts_with(app::batch_csv_header() + "\n"));
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 10);
  // The rows are the one batch row's: batch merge reads them back as mms rows, the same.
  const test_cli::TempDir dir("mms_batch_csv");
  fs::create_directories(dir.path);
  const std::string file = (dir.path / "mms.csv").string();
  common::write_file_atomically(file, csv);
  const std::vector<app::BatchRow> rows = app::read_batch_csvs({file});
  REQUIRE(rows.size() == items.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    CAPTURE(rows[i].world);
    CHECK(rows[i].kind == app::RunKind::mms);
    CHECK(rows[i].ok == items[i].ok);
    CHECK(rows[i].strategy == "sh " + kScripts + "by_size.sh");
    CHECK(rows[i].score.has_value());
    CHECK(app::format_batch_csv_row(rows[i]) == app::format_batch_csv_row(items[i].row));
  }
}

TEST_CASE("mms batch: an interrupted row is marked and left out of the totals and the CSV") {
  app::MmsBatchItem done;
  done.world = "a.txt";
  done.ran = true;
  done.ok = true;
  done.run.summary.reached_goal = true;
  app::MmsBatchItem stopped;
  stopped.world = "b.txt";
  stopped.ran = true;
  stopped.interrupted = true;
  stopped.run.mms.end = app::MmsEnd::interrupted;
  stopped.run.summary.reached_goal = true;  // reached before the signal: still not counted
  const std::string table = app::format_mms_batch_table({done, stopped}, 0.0, {});
  CHECK(table.find("total: 2 worlds, 1 ok, 0 failed, 1 interrupted; goal reached 1 of 1;") != std::string::npos);
  CHECK(app::format_mms_batch_csv({done, stopped}).find("b.txt") == std::string::npos);
}

TEST_CASE("mms --out: the files every run writes, summary.json with mms's stats and score, marks.txt the marks") {
  const fs::path dir = fs::temp_directory_path() / fmt::format("mms_out_{}", ::getpid());
  fs::remove_all(dir);
  app::RunOptions options;
  options.world = std::string(WORLDS_DIR) + "/open_room6x6.txt";
  options.output.quiet = true;
  options.output.out_dir = dir.string();
  app::MmsOptions mms;
  mms.command = {"sh", kScripts + "goal_then_loop.sh"};
  mms.until = app::MmsUntil::goal;
  std::ostringstream out;
  (void)app::run_mms_world(options, mms, out);
  std::ifstream file(dir / "summary.json");
  std::ostringstream text;
  text << file.rdbuf();
  const std::string json = text.str();
  // One report: the ending summary.json gives is the one printed (and a batch row's).
  CHECK(json.find("\"end\": \"reached\"") != std::string::npos);
  CHECK(out.str().find("\nend: reached (") != std::string::npos);
  CHECK(json.find("\"mms_end\"") == std::string::npos);
  CHECK(json.find("\"best_run_distance\": 4") != std::string::npos);
  CHECK(json.find("\"score\": 5.5") != std::string::npos);
  CHECK(json.find("\"goal\": \"reached\"") != std::string::npos);
  CHECK(json.find("\"sim_time_s\": ") != std::string::npos);
  // replay.html's table is the same report: the program's keys among the run's.
  std::ifstream replay(dir / "replay.html");
  std::ostringstream page;
  page << replay.rdbuf();
  CHECK(page.str().find("best_run_distance") != std::string::npos);
  for (const char *name : {"marks.txt", "map.png", "truth.png", "map.pgm", "map.yaml", "trace.csv", "replay.html"}) {
    INFO(name);
    CHECK(fs::is_regular_file(dir / name));
  }
  // trace.csv: the rows where something happens (as for a run with the lidar), the last one
  // the run's last step.
  std::ifstream trace(dir / "trace.csv");
  std::string line, last;
  while (std::getline(trace, line)) last = line;
  const std::string last_step = last.substr(0, last.find(','));
  CHECK(json.find(fmt::format("\"steps\": {},", last_step)) != std::string::npos);
  fs::remove_all(dir);
}

namespace {

// The names of the files directly in dir, sorted.
std::vector<std::string> file_names(const fs::path &dir) {
  std::vector<std::string> names;
  for (const fs::directory_entry &e : fs::directory_iterator(dir)) {
    if (e.is_regular_file()) names.push_back(e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

namespace {

// While alive, standard error (file descriptor 2) goes to `path`; text() ends that and reads it.
class StderrToFile {
 public:
  explicit StderrToFile(fs::path path) : path_(std::move(path)) {
    std::fflush(stderr);
    saved_ = ::dup(STDERR_FILENO);
    const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    ::dup2(fd, STDERR_FILENO);
    ::close(fd);
  }
  ~StderrToFile() { restore(); }
  StderrToFile(const StderrToFile &) = delete;
  StderrToFile &operator=(const StderrToFile &) = delete;
  std::string text() {
    restore();
    std::ifstream file(path_);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
  }

 private:
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_, STDERR_FILENO);
    ::close(saved_);
    saved_ = -1;
  }
  fs::path path_;
  int saved_ = -1;
};

}  // namespace

TEST_CASE("mms --out names every file it wrote, marks.txt and summary.json among them, in one line") {
  const test_cli::TempDir dir("mms_out_wrote_line");
  app::RunOptions options;
  options.world = std::string(WORLDS_DIR) + "/open_room6x6.txt";
  options.output.quiet = true;
  options.output.out_dir = (dir.path / "out").string();
  app::MmsOptions mms;
  mms.command = {"sh", kScripts + "goal_then_loop.sh"};
  mms.until = app::MmsUntil::goal;
  std::ostringstream out;
  fs::create_directories(dir.path);
  StderrToFile captured(dir.path / "stderr.txt");
  (void)app::run_mms_world(options, mms, out);
  const std::string err = captured.text();
  CHECK(err == fmt::format("wrote {}/: map.pgm, map.yaml, map.png, truth.png, summary.json, trace.csv, replay.html, "
                           "marks.txt\n",
                           options.output.out_dir));
}

TEST_CASE("run, room and mms --out write the same core files, each kind adding its own") {
  const std::vector<std::string> core{"map.pgm", "map.png",  "map.yaml",   "replay.html",
                                      "summary.json", "trace.csv", "truth.png"};
  const test_cli::TempDir run_dir("core_files_run");
  REQUIRE(test_cli::run({"run", std::string(WORLDS_DIR) + "/open_room6x6.txt", "--quiet", "--out",
                         run_dir.path.string()})
              .status == 0);
  CHECK(file_names(run_dir.path) == core);

  const test_cli::TempDir room_dir("core_files_room");
  REQUIRE(test_cli::run({"room", std::string(WORLDS_DIR) + "/ir_room.room", "--quiet", "--out",
                         room_dir.path.string()})
              .status == 0);
  std::vector<std::string> room = core;
  room.insert(room.end(), {"logodds.csv", "thresholded.txt"});
  std::sort(room.begin(), room.end());
  CHECK(file_names(room_dir.path) == room);

  const test_cli::TempDir mms_dir("core_files_mms");
  app::RunOptions options;
  options.world = std::string(WORLDS_DIR) + "/open_room6x6.txt";
  options.output.quiet = true;
  options.output.out_dir = mms_dir.path.string();
  app::MmsOptions mms;
  mms.command = {"sh", kScripts + "goal_then_loop.sh"};
  mms.until = app::MmsUntil::goal;
  std::ostringstream out;
  (void)app::run_mms_world(options, mms, out);
  std::vector<std::string> with_marks = core;
  with_marks.emplace_back("marks.txt");
  std::sort(with_marks.begin(), with_marks.end());
  CHECK(file_names(mms_dir.path) == with_marks);
}

namespace {

// Five cells north from the start of open_room6x6 with `robot` (empty: mms's default), as one
// moveForward 5 and as five moveForward: each a ramped leg with the robot's speed profile.
// --walls truth knows every side ahead open, so the five cells are one leg; in --walls sensed
// the leg reaches as far as the robot knows: never slower than cell by cell.
void check_one_leg_beats_five_moves(const std::string &robot, std::optional<double> cell_size_m) {
  const auto drive = [&](std::vector<std::string> counts, app::MmsWalls walls) {
    app::RunOptions options;
    options.world = std::string(WORLDS_DIR) + "/open_room6x6.txt";
    options.world_overrides.cell_size_m = cell_size_m;
    if (!robot.empty()) options.robot = robot;
    options.output.quiet = true;
    app::MmsOptions mms;
    mms.command = {"sh", kScripts + "forward.sh"};
    mms.command.insert(mms.command.end(), counts.begin(), counts.end());
    mms.walls = walls;
    std::ostringstream out;
    return app::run_mms_world(options, mms, out);
  };
  const maze::sim::RobotProfile &profile =
      robot.empty() ? maze::sim::default_profile() : maze::sim::find_profile(robot);
  REQUIRE(profile.speed_run);
  for (const app::MmsWalls walls : {app::MmsWalls::truth, app::MmsWalls::sensed}) {
    const app::MmsRun standing = drive({}, walls);
    const app::MmsRun one_leg = drive({"5"}, walls);
    const app::MmsRun five_moves = drive({"1", "1", "1", "1", "1"}, walls);
    for (const app::MmsRun *run : {&one_leg, &five_moves}) {
      INFO(run->mms.message);
      CHECK(run->mms.end == app::MmsEnd::exited);
      CHECK(run->summary.moves == 5);
      CHECK(run->mms.stats.total_distance() == 5);
      CHECK(run->mms.crashes == 0);
      CHECK(run->summary.visited == five_moves.summary.visited);
    }
    const double leg_s = one_leg.summary.sim_time_s - standing.summary.sim_time_s;
    const double moves_s = five_moves.summary.sim_time_s - standing.summary.sim_time_s;
    CAPTURE(leg_s);
    CAPTURE(moves_s);
    CHECK(leg_s > 0.0);
    CHECK(leg_s <= moves_s);
    if (walls == app::MmsWalls::truth) {
      CHECK(leg_s < 0.8 * moves_s);
      // Each single move speeds up and slows down: a cell takes a triangle's 2 sqrt(d / a) at
      // least, less 10 % for the speeds held a control step each.
      const double cell_m = cell_size_m.value_or(1.0);
      CHECK(moves_s >= 0.9 * 5.0 * 2.0 * std::sqrt(cell_m / profile.speed_run->acceleration_m_s2));
    }
  }
}

}  // namespace

TEST_CASE("mms: moveForward 5 drives one ramped leg, under 0.8 of five moveForward, the same five cells") {
  SUBCASE("the default robot (hambot), 1 m cells") { check_one_leg_beats_five_moves("", std::nullopt); }
  SUBCASE("the micromouse, 0.18 m cells") { check_one_leg_beats_five_moves("micromouse", 0.18); }
}
