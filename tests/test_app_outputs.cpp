// run --out's files read back by independent readers (libpng's, nlohmann's), --step, Ctrl-C,
// an unusable --out, and batch.
#include <doctest/doctest.h>

#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "png_reader.hpp"
#include "app/report/files_recorder.hpp"
#include "app/report/output_dir.hpp"
#include "app/batch/batch.hpp"
#include "app/report/outputs.hpp"
#include "app/run/run.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace {

namespace fs = std::filesystem;

using test_png::read_all;

// The lines of a text, without their '\n'.
std::vector<std::string> lines_of(const std::string &text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t end = text.find('\n'); end != std::string::npos; end = text.find('\n', start)) {
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

// A fresh directory under the system's temporary directory, removed at the end.
struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("maze_mapper_test_" + std::to_string(::getpid()) + "_" +
                                        std::to_string(counter()++));
    fs::remove_all(path);
  }
  ~TempDir() { fs::remove_all(path); }
  static int &counter() {
    static int n = 0;
    return n;
  }
};

app::RunOptions lab_options() {
  app::RunOptions o;
  o.world = std::string(WORLDS_DIR) + "/lab4x4.txt";
  o.simulation.noise = 0.0;
  o.output.quiet = true;
  return o;
}

struct Pgm {
  int width = 0;
  int height = 0;
  std::string pixels;
  unsigned char at(int col, int row) const {
    return static_cast<unsigned char>(pixels[static_cast<std::size_t>(row * width + col)]);
  }
};

Pgm read_pgm(const std::string &bytes) {
  // "P5\n# comment\nW H\n255\n" then W * H bytes.
  const std::vector<std::string> header = lines_of(bytes.substr(0, 200));
  REQUIRE(header.size() >= 4);
  REQUIRE(header[0] == "P5");
  REQUIRE(header[1].front() == '#');
  Pgm pgm;
  REQUIRE(std::sscanf(header[2].c_str(), "%d %d", &pgm.width, &pgm.height) == 2);
  REQUIRE(header[3] == "255");
  const std::size_t offset = header[0].size() + header[1].size() + header[2].size() + header[3].size() + 4;
  pgm.pixels = bytes.substr(offset);
  REQUIRE(pgm.pixels.size() == static_cast<std::size_t>(pgm.width * pgm.height));
  return pgm;
}

using test_png::Png;
using test_png::read_png;

int g_polls = 0;
bool interrupt_after_100_steps() { return ++g_polls > 100; }

}  // namespace

TEST_CASE("run --out writes the ROS map pair, PNG, JSON and CSV with the run's content") {
  const TempDir dir;
  app::RunOptions options = lab_options();
  options.output.out_dir = (dir.path / "out").string();
  options.output.trace_steps = true;  // the default form: the next case
  std::ostringstream out;
  const app::RunSummary summary = app::run_and_write(options, out);
  REQUIRE(summary.reason == robot::EndReason::done);

  const Pgm pgm = read_pgm(read_all(dir.path / "out" / "map.pgm"));
  CHECK(pgm.width == 12);
  CHECK(pgm.height == 12);
  // Row 0 is the north edge: the NW corner and the whole north band are walls; the centre
  // of the start cell (0,0), bottom-left, is free.
  CHECK(pgm.at(0, 0) == 0);
  CHECK(pgm.at(1, 0) == 0);
  CHECK(pgm.at(1, 10) == 254);
  CHECK(pgm.at(0, 10) == 0);  // the west edge
  for (const char p : pgm.pixels) {
    const auto v = static_cast<unsigned char>(p);
    CHECK((v == 0 || v == 254 || v == 205));
  }

  const std::string yaml = read_all(dir.path / "out" / "map.yaml");
  CHECK(yaml ==
        "image: map.pgm\nresolution: 0.333333\norigin: [0.000000, 0.000000, 0.0]\nnegate: 0\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n");

  // map.png and truth.png: tones and marks in tests/test_app_map_picture.cpp and
  // tests/test_app_truth_picture.cpp.
  const Png png = read_png(read_all(dir.path / "out" / "map.png"));
  CHECK(png.width > 12 * 34);  // 12 * 34 = 408 px of map, the axes, the legend
  CHECK(png.height > 12 * 34);
  mapping::GridGeometry lab;  // 4 x 4 cells, K 3
  lab.width_cells = lab.height_cells = 4;
  const app::PointPx origin = app::map_origin_px(lab);
  const std::vector<int> corner = png.at(static_cast<int>(origin.x) + 17, static_cast<int>(origin.y) + 17);  // NW corner sub-cell: a wall, dark
  CHECK(corner[0] == corner[2]);
  CHECK(corner[0] <= 70);  // one update of l(0.6) already 70
  const Png truth = read_png(read_all(dir.path / "out" / "truth.png"));
  CHECK(truth.width > 4 * 102);

  const nlohmann::json json = nlohmann::json::parse(read_all(dir.path / "out" / "summary.json"));
  CHECK(json.at("size") == "4x4");
  CHECK(json.at("steps") == summary.steps);
  CHECK(json.at("moves") == 29);
  CHECK(json.at("visited") == 16);
  CHECK(json.at("coverage") == 100.0);
  CHECK(json.at("wall_accuracy") == 100.0);
  CHECK(json.at("end") == "done");
  CHECK(json.at("options").at("subcells") == 3);
  CHECK(json.at("options").at("simulation").at("noise") == 0.0);
  CHECK(json.at("options").at("sensor").at("p_occ") == 0.6);
  CHECK(json.at("options").at("sensor").at("clamp").is_null());
  CHECK(json.at("options").at("world_overrides").dump() == R"({"cell_size_m":null,"centre_goals":false,"goals":null,"random_start":false,"start":null,"start_m":null,"start_position":null})");

  const std::vector<std::string> csv = lines_of(read_all(dir.path / "out" / "trace.csv"));
  REQUIRE(!csv.empty());
  CHECK(csv[0] == "step,time_s,true_x_m,true_y_m,true_yaw_rad,cell_x,cell_y,action,subcells_updated,"
                  "gps_x_m,gps_y_m,imu_yaw_rad");
  // hambot's lidar is fixed: the first scan is at once, in the start step, and the robot
  // drives off the next. Its GPS and IMU have no noise: the pose it reads is the true one.
  CHECK(csv[1] == "1,0.032,0.5000,0.5000,1.5708,0,0,start,8,0.5000,0.5000,1.5708");
  CHECK(csv[4] == "4,0.128,0.5000,0.5432,1.5708,0,0,drive,0,0.5000,0.5432,1.5708");
  std::size_t updated = 0;
  for (std::size_t i = 1; i < csv.size(); ++i) {
    std::size_t at = 0;
    for (int column = 0; column < 8; ++column) at = csv[i].find(',', at) + 1;  // to subcells_updated
    updated += std::stoul(csv[i].substr(at, csv[i].find(',', at) - at));
  }
  CHECK(static_cast<std::int64_t>(csv.size()) - 1 == summary.steps);
  CHECK(updated > 0);

  // Nothing but the seven files (no temporaries).
  CHECK(fs::exists(dir.path / "out" / "replay.html"));
  CHECK(std::distance(fs::directory_iterator(dir.path / "out"), fs::directory_iterator()) == 7);
}

TEST_CASE("an output folder writes only the names it checked against the inputs, a folder's files in it") {
  const TempDir dir;
  app::OutputDir out(dir.path.string(), {}, {"marks.txt"});
  CHECK(fs::is_directory(dir.path));
  out.write("marks.txt", "marks\n");
  out.write("snapshots/t5s.png", "png");
  CHECK_THROWS_AS(out.write("notes.txt", "x"), std::logic_error);
  CHECK_THROWS_AS(out.write("other/01.png", "x"), std::logic_error);
  CHECK(read_all((dir.path / "marks.txt").string()) == "marks\n");
  CHECK(read_all((dir.path / "snapshots" / "t5s.png").string()) == "png");
  CHECK_FALSE(fs::exists(dir.path / "notes.txt"));
  CHECK_FALSE(fs::exists(dir.path / "other"));
}

TEST_CASE("an output folder refuses a kind's own file that is an input, before writing anything") {
  const TempDir dir;
  fs::create_directories(dir.path);
  const std::string program = (dir.path / "marks.txt").string();
  common::write_file_atomically(program, "#!/bin/sh\n");
  CHECK_THROWS_WITH_AS(app::OutputDir(dir.path.string(), {{"the program", program}}, {"marks.txt"}),
                       ("--out " + program + " is also an input (the program " + program + "): refusing to overwrite it")
                           .c_str(),
                       common::InputError);
  CHECK(read_all(program) == "#!/bin/sh\n");
}

TEST_CASE("finishing an output folder removes the core files an earlier run left and this one did not write") {
  const TempDir dir;
  fs::create_directories(dir.path / "snapshots");
  for (const char *stale : {"replay.html", "map.svg", "snapshots/01.png"}) {
    common::write_file_atomically((dir.path / stale).string(), "stale");
  }
  common::write_file_atomically((dir.path / "notes.txt").string(), "the user's");
  app::OutputDir out(dir.path.string(), {});
  out.write("summary.json", "{}\n");
  out.finish();
  CHECK(fs::exists(dir.path / "summary.json"));
  CHECK_FALSE(fs::exists(dir.path / "replay.html"));
  CHECK_FALSE(fs::exists(dir.path / "map.svg"));
  CHECK_FALSE(fs::exists(dir.path / "snapshots"));
  CHECK(read_all((dir.path / "notes.txt").string()) == "the user's");
}

TEST_CASE("finishing an output folder removes a kind's own file an earlier run left; a command's own names leave a run's files") {
  const TempDir dir;
  fs::create_directories(dir.path);
  for (const char *stale : {"wave.png", "summary.json", "logodds_step9.csv"}) {
    common::write_file_atomically((dir.path / stale).string(), "stale");
  }
  {
    // A room run that draws no wave this time: an earlier run's wave.png goes.
    app::OutputDir out(dir.path.string(), {}, {"logodds.csv", "wave.png"});
    out.write("logodds.csv", "1\n");
    out.write("summary.json", "{}\n");
    out.finish();
  }
  CHECK_FALSE(fs::exists(dir.path / "wave.png"));
  {
    // map-log's own names alone: the run's summary.json stays.
    app::OutputDir out(dir.path.string(), {}, app::OwnNamesOnly{{"logodds.csv", "logodds_step5.csv"}});
    out.write("logodds.csv", "2\n");
    CHECK_THROWS_AS(out.write("summary.json", "x"), std::logic_error);
    out.finish();
  }
  CHECK(read_all((dir.path / "summary.json").string()) == "{}\n");
  CHECK(read_all((dir.path / "logodds.csv").string()) == "2\n");
  CHECK(read_all((dir.path / "logodds_step9.csv").string()) == "stale");  // not among the names declared
}

TEST_CASE("an unusable --out is an error before the run, and leaves nothing") {
  const TempDir dir;
  fs::create_directories(dir.path);
  common::write_file_atomically((dir.path / "file").string(), "x");
  app::RunOptions options = lab_options();

  options.output.out_dir = (dir.path / "file").string();
  std::ostringstream out;
  CHECK_THROWS_WITH_AS(app::run_and_write(options, out),
                       ("--out " + options.output.out_dir + ": exists and is not a directory").c_str(),
                       common::InputError);
  CHECK(out.str().empty());

  options.output.out_dir = (dir.path / "file" / "a" / "b").string();
  CHECK_THROWS_WITH_AS(app::run_and_write(options, out),
                       ("--out " + options.output.out_dir + ": cannot create the directory: Not a directory").c_str(),
                       common::InputError);
  CHECK(out.str().empty());
  CHECK(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()) == 1);

  // A bad world is found before the directory is made.
  options.world = std::string(TEST_DATA_DIR) + "/worlds/inconsistent.num";
  options.output.out_dir = (dir.path / "new").string();
  CHECK_THROWS_AS(app::run_and_write(options, out), common::InputError);
  CHECK_FALSE(fs::exists(dir.path / "new"));
}

TEST_CASE("--step: Enter goes on, q stops the run cleanly with a summary") {
  app::RunOptions options = lab_options();
  options.output.step = true;
  std::istringstream in("\n\nq\n");
  app::RunControls controls;
  controls.in = &in;
  std::ostringstream out;
  const app::RunSummary summary = app::run_and_write(options, out, controls);
  CHECK(summary.reason == robot::EndReason::stopped);
  CHECK(summary.moves == 2);
  CHECK(app::exit_status(summary) == 0);
  CHECK(out.str().find("end: stopped (quit with q)\n") != std::string::npos);

  std::istringstream short_input("\n");  // input ends: the run goes on to its end
  controls.in = &short_input;
  const app::RunSummary full = app::run_and_write(options, out, controls);
  CHECK(full.reason == robot::EndReason::done);
  CHECK(full.moves == 29);
}

TEST_CASE("the default trace keeps the first and last steps and every step where the action or cell changes "
          "or a scan updates the map, as --trace-steps has them") {
  const TempDir dir;
  app::RunOptions options = lab_options();
  options.output.out_dir = (dir.path / "every").string();
  options.output.trace_steps = true;
  std::ostringstream out;
  const app::RunSummary summary = app::run_and_write(options, out);
  options.output.out_dir = (dir.path / "default").string();
  options.output.trace_steps = false;
  app::run_and_write(options, out);
  const std::vector<std::string> every = lines_of(read_all(dir.path / "every" / "trace.csv"));
  const std::vector<std::string> thinned = lines_of(read_all(dir.path / "default" / "trace.csv"));
  REQUIRE(static_cast<std::int64_t>(every.size()) == summary.steps + 1);
  const auto fields = [](const std::string &row) {
    std::vector<std::string> f;
    std::stringstream in(row);
    for (std::string field; std::getline(in, field, ',');) f.push_back(field);
    return f;
  };
  std::vector<std::string> expected{every[0]};
  for (std::size_t i = 1; i < every.size(); ++i) {
    const std::vector<std::string> now = fields(every[i]);
    const bool first = i == 1;
    const bool last = i + 1 == every.size();
    bool changed = first || last || now[8] != "0";
    if (!first) {
      const std::vector<std::string> before = fields(every[i - 1]);
      changed = changed || now[5] != before[5] || now[6] != before[6] || now[7] != before[7];
    }
    if (changed) expected.push_back(every[i]);
  }
  CHECK(thinned == expected);
  CHECK(thinned.size() * 10 < every.size());  // 127 rows of 2,697 on lab4x4
}

TEST_CASE("an interrupted run's trace has a row for every step it counts") {
  const TempDir dir;
  app::RunOptions options = lab_options();
  options.output.out_dir = (dir.path / "out").string();
  options.output.trace_steps = true;
  g_polls = 0;
  app::RunControls controls;
  controls.interrupted = interrupt_after_100_steps;
  std::ostringstream out;
  const app::RunSummary summary = app::run_and_write(options, out, controls);
  CHECK(summary.steps == 100);
  CHECK(lines_of(read_all(dir.path / "out" / "trace.csv")).size() == 101);  // the header and 100 rows
}

TEST_CASE("an interrupt refuses the next control step; exit status 130") {
  app::RunOptions options = lab_options();
  g_polls = 0;
  app::RunControls controls;
  controls.interrupted = interrupt_after_100_steps;
  std::ostringstream out;
  const app::RunSummary summary = app::run_and_write(options, out, controls);
  CHECK(summary.reason == robot::EndReason::stopped);
  CHECK(summary.interrupted);
  CHECK(summary.steps == 100);  // polled before each control step: the 101st poll refuses the 101st
  CHECK(app::exit_status(summary) == 130);
  CHECK(out.str().find("end: stopped (interrupted by Ctrl-C)\n") != std::string::npos);
}

TEST_CASE("batch: a bad world is reported and does not stop the others; input order") {
  const std::string good = std::string(WORLDS_DIR) + "/lab4x4.txt";
  const std::string bad = std::string(TEST_DATA_DIR) + "/worlds/inconsistent.num";
  const std::string eight = std::string(WORLDS_DIR) + "/maze8x8.txt";
  app::RunOptions options = lab_options();
  std::size_t calls = 0;
  const std::vector<app::BatchItem> items =
      app::run_batch(options, {eight, bad, good}, 3, [&](std::size_t, std::size_t) { ++calls; });
  REQUIRE(items.size() == 3);
  CHECK(calls == 3);
  CHECK(items[0].world == eight);
  CHECK(items[0].ok);
  CHECK(items[0].summary.width == 8);
  CHECK(items[1].bad_input);
  CHECK(items[1].error.find(bad + ":25:11: error:") == 0);
  CHECK(items[2].ok);
  CHECK(items[2].summary.moves == 29);
  CHECK(app::batch_exit_status(items) == 1);
  const std::string table = app::format_batch_table(items, 1.0);
  CHECK(table.find(eight) < table.find(bad));
  CHECK(table.find(bad) < table.find(good));
  CHECK(table.find("total: 3 worlds, 2 ok, 1 failed; moves 144;") != std::string::npos);
  const std::string csv = app::format_batch_csv(items);
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 4);

  const std::vector<app::BatchItem> all_bad = app::run_batch(options, {bad, bad}, 1, {});
  CHECK(app::batch_exit_status(all_bad) == 2);

  // The same table with one job as with three.
  const std::vector<app::BatchItem> serial = app::run_batch(options, {eight, bad, good}, 1, {});
  for (std::size_t i = 0; i < 3; ++i) CHECK(serial[i].summary.moves == items[i].summary.moves);
}

TEST_CASE("batch: names sort naturally") {
  CHECK(app::natural_less("s4.txt", "s10.txt"));
  CHECK_FALSE(app::natural_less("s10.txt", "s4.txt"));
  CHECK(app::natural_less("maze2x", "maze10"));
  CHECK(app::natural_less("a", "b"));
  CHECK(app::natural_less("a", "a1"));
  CHECK(app::natural_less("s04", "s4") != app::natural_less("s4", "s04"));  // strict: leading zeros decide last
  CHECK_FALSE(app::natural_less("s4", "s4"));
  CHECK(app::natural_less("x9y", "x10a"));
  CHECK(app::natural_less("x10a", "x10b"));
}

namespace {

void write_bytes(const fs::path &path, const std::string &bytes) {
  std::FILE *file = std::fopen(path.c_str(), "wb");
  REQUIRE(file != nullptr);
  std::fwrite(bytes.data(), 1, bytes.size(), file);
  std::fclose(file);
}

// A folder as users keep them: mazes (one broken), a README and a picture.
struct MazeFolder {
  TempDir dir;
  MazeFolder() {
    fs::create_directories(dir.path);
    const std::string lab = read_all(std::string(WORLDS_DIR) + "/lab4x4.txt");
    write_bytes(dir.path / "s10.txt", lab);
    write_bytes(dir.path / "s4.txt", lab);
    write_bytes(dir.path / "broken.num", read_all(std::string(TEST_DATA_DIR) + "/worlds/inconsistent.num"));
    write_bytes(dir.path / "README.md", "# Mazes\nFrom the 2019 contest.\n");
    write_bytes(dir.path / "photo.png", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
  }
  std::string operator/(const char *name) const { return (dir.path / name).string(); }
};

}  // namespace

TEST_CASE("batch: a folder's maze files are rows, broken ones with their error; other files are skipped by name") {
  const MazeFolder folder;
  const app::WorldList list = app::expand_worlds({folder.dir.path.string()});
  CHECK(list.worlds == std::vector<std::string>{folder / "broken.num", folder / "s4.txt", folder / "s10.txt"});
  CHECK(list.skipped == std::vector<std::string>{folder / "README.md", folder / "photo.png"});

  // A file named on the command line is a row whatever it is; a missing one too.
  const std::string missing = folder / "missing.txt";
  const app::WorldList named = app::expand_worlds({missing, folder / "README.md"});
  CHECK(named.worlds == std::vector<std::string>{missing, folder / "README.md"});
  CHECK(named.skipped.empty());

  std::vector<std::string> worlds = list.worlds;
  worlds.push_back(missing);
  const std::vector<app::BatchItem> items = app::run_batch(lab_options(), worlds, 2, {});
  REQUIRE(items.size() == 4);
  CHECK_FALSE(items[0].ran);
  CHECK(items[0].bad_input);
  CHECK(items[0].error.find(folder / "broken.num" + ":25:11: error:") == 0);
  CHECK(items[1].ok);
  CHECK(items[2].ok);
  CHECK_FALSE(items[3].ran);
  CHECK(items[3].error.find("cannot read " + missing) != std::string::npos);
  CHECK(app::batch_exit_status(items) == 1);

  const std::vector<std::string> table = lines_of(app::format_batch_table(items, 1.0, list.skipped));
  REQUIRE(table.size() == 6);
  CHECK(table[0].ends_with("ms  end"));
  CHECK(table[0].find("wall_accuracy") != std::string::npos);
  CHECK(table[1].find(items[0].error) != std::string::npos);
  CHECK(table[2].ends_with("  done"));
  CHECK(table[4].find(items[3].error) != std::string::npos);
  CHECK(table[5].find("total: 4 worlds, 2 ok, 2 failed;") == 0);
  CHECK(table[5].ends_with("; 2 skipped, not mazes: " + (folder / "README.md") + ", " + (folder / "photo.png")));
}

TEST_CASE("batch: a run that ends incomplete or without progress is a failed row with its ending") {
  app::BatchItem done;
  done.world = "a.txt";
  done.ran = done.ok = true;
  done.summary.width = done.summary.height = 4;
  done.report = app::run_report(lab_options(), done.summary);
  app::BatchItem incomplete = done;
  incomplete.world = "b.txt";
  incomplete.ok = false;
  incomplete.summary.reason = robot::EndReason::incomplete;
  incomplete.summary.message = "3 of 16 reachable cells never visited";
  incomplete.report = app::run_report(lab_options(), incomplete.summary);
  const std::vector<std::string> table = lines_of(app::format_batch_table({done, incomplete}, 1.0));
  CHECK(table[2].ends_with("  incomplete (3 of 16 reachable cells never visited)"));
  CHECK(table[3].find("total: 2 worlds, 1 ok, 1 failed;") == 0);
  CHECK(app::batch_exit_status({done, incomplete}) == 1);
}

namespace {
int g_batch_polls = 0;
bool interrupt_batch_after_100_polls() { return ++g_batch_polls > 100; }
}  // namespace

TEST_CASE("batch: Ctrl-C stops the run in flight and starts no other; the CSV holds the finished runs") {
  const std::string lab = std::string(WORLDS_DIR) + "/lab4x4.txt";
  const std::string eight = std::string(WORLDS_DIR) + "/maze8x8.txt";
  g_batch_polls = 0;
  // One job: lab4x4 needs more than 100 steps, so the interrupt comes during its run.
  const std::vector<app::BatchItem> items =
      app::run_batch(lab_options(), {lab, eight, lab}, 1, {}, interrupt_batch_after_100_polls);
  REQUIRE(items.size() == 3);
  CHECK(items[0].interrupted);
  CHECK(items[0].summary.steps == 99);  // one poll before it starts, then one before each step
  CHECK(items[1].interrupted);
  CHECK_FALSE(items[1].ran);
  CHECK(items[1].error == "not run (interrupted by Ctrl-C)");
  CHECK(app::batch_exit_status(items) == 130);
  CHECK(app::format_batch_csv(items) == app::batch_csv_header() + "\n");
  const std::string table = app::format_batch_table(items, 1.0);
  CHECK(table.find("total: 3 worlds, 0 ok, 0 failed, 3 interrupted;") != std::string::npos);
}

TEST_CASE("trace.csv's cell is the console's at the same step; --no-trace writes none") {
  const TempDir dir;
  app::RunOptions options = lab_options();
  options.output.quiet = false;
  options.output.out_dir = (dir.path / "out").string();
  options.output.trace_steps = true;
  std::ostringstream out;
  app::run_and_write(options, out);
  const std::vector<std::string> csv = lines_of(read_all(dir.path / "out" / "trace.csv"));
  int compared = 0;
  for (const std::string &line : lines_of(out.str())) {
    long step = 0;
    int x = 0;
    int y = 0;
    if (std::sscanf(line.c_str(), "step %ld  cell (%d,%d)", &step, &x, &y) != 3) continue;
    REQUIRE(step >= 1);
    REQUIRE(static_cast<std::size_t>(step) < csv.size());
    const std::string &row = csv[static_cast<std::size_t>(step)];
    CAPTURE(line);
    CHECK(row.starts_with(std::to_string(step) + ","));
    std::vector<std::string> fields;
    std::stringstream fs_in(row);
    for (std::string f; std::getline(fs_in, f, ',');) fields.push_back(f);
    REQUIRE(fields.size() == 12);  // and the GPS and IMU columns
    CHECK(fields[5] == std::to_string(x));
    CHECK(fields[6] == std::to_string(y));
    ++compared;
  }
  CHECK(compared == 30);  // the start and 29 moves

  options.output.quiet = true;
  options.output.trace = false;
  options.output.out_dir = (dir.path / "no_trace").string();
  app::run_and_write(options, out);
  CHECK_FALSE(fs::exists(dir.path / "no_trace" / "trace.csv"));
  CHECK(fs::exists(dir.path / "no_trace" / "map.png"));
}

TEST_CASE("exit status: a wrong map fails; the step limit fails unless the user set it") {
  app::RunSummary s;
  CHECK(app::exit_status(s) == 0);
  s.reason = robot::EndReason::wrong_map;
  CHECK(app::exit_status(s) == 1);
  s.reason = robot::EndReason::max_steps;
  s.max_steps_asked = true;
  CHECK(app::exit_status(s) == 0);
  s.max_steps_asked = false;
  CHECK(app::exit_status(s) == 1);
}
