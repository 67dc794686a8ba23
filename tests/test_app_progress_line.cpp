// The progress lines a long run and a batch draw on a terminal: the percentage of a known
// end and, for a batch, the time left at the rate so far; and the line as a run's observer,
// drawn by a maze run, a room run and an mms program's run alike and cleared when the run
// ends.

#include <doctest/doctest.h>

#include <fcntl.h>
#include <unistd.h>

#include <limits>
#include <sstream>
#include <string>

#include "app/mms/mms_session.hpp"
#include "app/run/metric/run.hpp"
#include "app/run/progress_line.hpp"
#include "app/run/run.hpp"
#include "maze/world/world.hpp"

TEST_CASE("progress: a clock reads m:ss under an hour, h:mm:ss from one, whole seconds rounded") {
  CHECK(app::format_clock(0.0) == "0:00");
  CHECK(app::format_clock(7.4) == "0:07");
  CHECK(app::format_clock(59.6) == "1:00");
  CHECK(app::format_clock(760.0) == "12:40");
  CHECK(app::format_clock(3725.0) == "1:02:05");
  CHECK(app::format_clock(-3.0) == "0:00");
  CHECK(app::format_clock(std::numeric_limits<double>::infinity()) == "0:00");
}

TEST_CASE("progress: the percentage is rounded down, so 100% only when all is done") {
  CHECK(app::percent_done(0, 20) == 0);
  CHECK(app::percent_done(6, 20) == 30);
  CHECK(app::percent_done(199, 200) == 99);
  CHECK(app::percent_done(20, 20) == 100);
  CHECK(app::percent_done(0, 0) == 100);
}

TEST_CASE("progress: a batch shows its bar, the worlds done of all, and the time left at the rate so far") {
  // 6 worlds in 18 s: 3 s a world, 14 to go: 42 s.
  CHECK(app::format_batch_progress(6, 20, 18.0) == "[#########                     ]  30%  6/20 worlds  0:42 left");
  CHECK(app::format_batch_progress(1, 3, 100.0) == "[##########                    ]  33%  1/3 worlds  3:20 left");
  // No rate before the first world, nothing left after the last.
  CHECK(app::format_batch_progress(0, 4, 5.0) == "[                              ]   0%  0/4 worlds");
  CHECK(app::format_batch_progress(4, 4, 5.0) == "[##############################] 100%  4/4 worlds");
}

TEST_CASE("progress: a run shows the cells visited of the reachable ones, as a percentage") {
  CHECK(app::format_run_progress(41, 30, 36, 96.43, 1.24) ==
        "moves 41  visited 30/36 reachable cells (83%)  sim 96.4 s  elapsed 1.2 s");
  CHECK(app::format_run_progress(0, 1, 1, 0.0, 0.0) == "moves 0  visited 1/1 reachable cells (100%)  sim 0.0 s  elapsed 0.0 s");
}

TEST_CASE("progress: a run in metres shows the reachable free cells observed, as a percentage") {
  CHECK(app::format_metres_progress(1200, 830, 8906, 38.43, 1.24) ==
        "steps 1200  observed 830/8906 reachable free cells (9%)  sim 38.4 s  elapsed 1.2 s");
}

namespace {

// What a run drew on the write end of a pipe given as its progress_fd.
template <typename Run>
std::string progress_drawn_by(Run run) {
  int fds[2];
  REQUIRE(::pipe(fds) == 0);
  ::fcntl(fds[0], F_SETFL, O_NONBLOCK);
  run(fds[1]);
  ::close(fds[1]);
  std::string drawn;
  char buffer[4096];
  for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;) drawn.append(buffer, static_cast<std::size_t>(n));
  ::close(fds[0]);
  return drawn;
}

}  // namespace

TEST_CASE("progress: a maze run, a room run and an mms program's run draw the line as the run goes and clear it at the end") {
  const std::string clear = "\r\x1b[K";
  const std::string maze_line = progress_drawn_by([](int fd) {
    app::RunOptions o;
    o.world = std::string(WORLDS_DIR) + "/lab4x4.txt";
    o.output.quiet = true;
    std::ostringstream out;
    app::RunControls controls;
    controls.progress_fd = fd;
    app::run_maze(o, maze::load_world(o.world).maze(), out, controls);
  });
  CHECK(maze_line.find("moves 0  visited 1/16 reachable cells") != std::string::npos);
  CHECK(maze_line.ends_with(clear));
  const std::string room_line = progress_drawn_by([](int fd) {
    app::RunOptions o = app::metres_run_options();
    o.world = std::string(WORLDS_DIR) + "/ir_room.room";
    o.time_limit_s = 2.0;
    o.output.quiet = true;
    std::ostringstream out;
    app::run_metric_world(maze::load_world(o.world), o, out, std::chrono::steady_clock::now(), nullptr, nullptr,
                          nullptr, fd);
  });
  CHECK(room_line.find("steps 1  observed ") != std::string::npos);
  CHECK(room_line.find(" reachable free cells (") != std::string::npos);
  CHECK(room_line.ends_with(clear));
  const std::string mms_line = progress_drawn_by([](int fd) {
    app::RunOptions o;
    o.world = std::string(WORLDS_DIR) + "/lab4x4.txt";
    o.output.quiet = true;
    app::MmsOptions mms;
    mms.command = {"sh", std::string(TEST_DATA_DIR) + "/mms/readme_conversation.sh"};
    std::ostringstream out;
    app::RunControls controls;
    controls.progress_fd = fd;
    app::run_mms_world(o, mms, out, controls);
  });
  CHECK(mms_line.find("moves 0  visited 1/") != std::string::npos);
  CHECK(mms_line.find(" reachable cells (") != std::string::npos);
  CHECK(mms_line.ends_with(clear));
}
