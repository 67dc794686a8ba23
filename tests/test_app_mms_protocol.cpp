// The mms protocol apart from any robot: lines read into commands as mms reads them, and
// mms's stats and score (its README's Scorekeeping section and its Stats source).

#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "app/mms/mms_marks.hpp"
#include "app/mms/mms_protocol.hpp"

using app::MmsStats;
using app::MmsVerb;
using app::parse_mms_line;

TEST_CASE("mms lines: every command of the README reads, with its arguments") {
  struct Row {
    const char *line;
    MmsVerb verb;
  };
  const Row rows[] = {
      {"mazeWidth", MmsVerb::maze_width},         {"mazeHeight", MmsVerb::maze_height},
      {"wallFront", MmsVerb::wall_front},         {"wallRight", MmsVerb::wall_right},
      {"wallLeft", MmsVerb::wall_left},           {"moveForward", MmsVerb::move_forward},
      {"turnRight", MmsVerb::turn_right},         {"turnRight90", MmsVerb::turn_right},
      {"turnLeft", MmsVerb::turn_left},           {"turnLeft90", MmsVerb::turn_left},
      {"turnLeft45", MmsVerb::turn_left_45},      {"moveForwardHalf 3", MmsVerb::move_forward_half},
      {"setWall 0 0 W", MmsVerb::set_wall},       {"clearWall 1 2 e", MmsVerb::clear_wall},
      {"setColor 0 1 r", MmsVerb::set_color},     {"clearColor 0 1", MmsVerb::clear_color},
      {"clearAllColor", MmsVerb::clear_all_color}, {"setText 0 1 whoops", MmsVerb::set_text},
      {"clearText 0 1", MmsVerb::clear_text},     {"clearAllText", MmsVerb::clear_all_text},
      {"wasReset", MmsVerb::was_reset},           {"ackReset", MmsVerb::ack_reset},
      {"getStat score", MmsVerb::get_stat},       {"wallBackLeft", MmsVerb::wall_back_left},
  };
  for (const Row &row : rows) {
    INFO(row.line);
    const app::ParsedLine p = parse_mms_line(row.line);
    REQUIRE(p.command);
    CHECK(p.command->verb == row.verb);
  }
  CHECK(parse_mms_line("moveForward 5").command->count == 5);
  CHECK(parse_mms_line("moveForward abc").command->count == 0);  // mms reads it as 0: crash
  CHECK(parse_mms_line("moveForward 99999999999").command->count == 0);  // past an int: 0 too, as Qt's toInt
  CHECK(parse_mms_line("moveForward 2147483647").command->count == 2147483647);  // the mouse crashes it
  CHECK(parse_mms_line("setWall 0 0 W").command->side == 'w');  // the README's own example writes W
  const auto text = parse_mms_line("setText 3 -1 two words and more").command;
  CHECK(text->x == 3);
  CHECK(text->y == -1);
  CHECK(text->text == "two words ");  // at most 10 characters
  CHECK(parse_mms_line("setText 1 2 tab\there").command->text == "tab?here");
  CHECK(parse_mms_line("  wallFront  ").command);  // blanks around tokens, as mms splits
}

TEST_CASE("mms lines: what mms would ignore is no command, and says why") {
  CHECK(parse_mms_line("hello, simulator").error == "unknown command");
  CHECK(parse_mms_line("").error == "empty line");
  CHECK(parse_mms_line("mazeWidth 3").error == "mazeWidth takes no argument");
  CHECK(parse_mms_line("wallFront 1 2").error == "wallFront takes at most one argument");
  CHECK(parse_mms_line("setWall 0 0 x").error == "setWall takes X Y D (D one of n e s w)");
  CHECK(parse_mms_line("setWall a 0 n").error == "setWall takes X Y D (D one of n e s w)");
  CHECK(parse_mms_line("setColor 0 0 z").error == "setColor: 'z' is no colour (kbacgorwyBCAGORVY)");
  CHECK(parse_mms_line("setText x 1 hi").error == "setText takes X Y TEXT");
  CHECK(parse_mms_line("getStat").error == "getStat takes a stat name");
  CHECK(parse_mms_line("getStat foo").error == "getStat: no stat 'foo'");
  CHECK(parse_mms_line("wallfront").error == "unknown command");  // case matters, as in mms
}

TEST_CASE("mms stats: the README's effective distance, runs, the best run and the score") {
  MmsStats s;
  CHECK(s.stat("score") == "2000");
  CHECK(s.stat("best-run-distance") == "-1");
  CHECK(s.stat("total-distance") == "0");
  CHECK_FALSE(s.stat("no-such-stat"));
  // A search: from the start 5 cells straight (effective 3.5), a turn, 2 cells, into the goal.
  s.start_run();
  s.add_distance(5);
  s.add_turn();
  s.add_distance(2);
  s.finish_run();
  CHECK(s.total_distance() == 7);
  CHECK(s.total_effective_distance() == doctest::Approx(5.5));
  CHECK(s.best_run_turns() == 1);
  CHECK(s.best_run_effective_distance() == doctest::Approx(5.5));
  // score = best turns + best effective + 0.1 * (total turns + total effective)
  CHECK(s.score() == doctest::Approx(1 + 5.5 + 0.1 * (1 + 5.5)));
  CHECK(s.stat("score") == "7.15");
  // Back to the start (not a run: it did not start there), then a reset's penalty on the
  // next run, which is worse and leaves the best run as it was.
  s.add_turn();
  s.add_turn();
  s.add_distance(7);
  s.end_unfinished_run();
  s.penalize_for_reset();
  s.start_run();
  s.add_distance(1);
  s.finish_run();
  CHECK(s.best_run_effective_distance() == doctest::Approx(5.5));
  CHECK(s.current_run_effective_distance() == doctest::Approx(16.0));
  CHECK(s.total_turns() == 3);
  CHECK(s.total_effective_distance() == doctest::Approx(5.5 + 4.5 + 15 + 1));
  // A better run replaces the best one.
  s.start_run();
  s.add_distance(3);
  s.finish_run();
  CHECK(s.best_run_distance() == 3);
  CHECK(s.best_run_turns() == 0);
  CHECK(s.stat("best-run-effective-distance") == "2.5");
}

TEST_CASE("mms marks: a wall on both sides, text before colour, mms's colour as the background") {
  app::MmsMarks m(2, 1);
  m.set_wall(0, 0, 'e', true);
  CHECK(m.walls[0] == 2);
  CHECK(m.walls[1] == 8);
  m.texts[0] = "12345";
  m.colors[1] = 'r';
  CHECK(app::render_marks(m, false) ==
        "o   o   o\n"
        " 123|r   \n"
        "o   o   o\n"
        "text (0,0): 12345\n");
  CHECK(app::render_marks(m, true).find("\x1b[48;2;204;0;0m\x1b[97mr  \x1b[0m") != std::string::npos);
  m.set_wall(0, 0, 'e', false);
  CHECK(m.walls[1] == 0);
}

TEST_CASE("mms marks: a cell outside the maze is ignored, its neighbour inside too, whatever its number") {
  app::MmsMarks m(2, 2);
  const std::vector<unsigned char> none(4, 0);
  // The west wall of (0,0) is the east wall of (-1,0): mms sets neither, as (-1,0) is outside.
  m.apply(*parse_mms_line("setWall -1 0 e").command);
  m.apply(*parse_mms_line("setWall 0 2 s").command);
  CHECK(m.walls == none);
  // The largest and smallest ints: no index computed, no neighbour's number overflowed.
  for (const char *line : {"setWall 2147483647 0 e", "setWall -2147483648 0 w", "setWall 0 2147483647 n",
                           "setWall 0 -2147483648 s", "setColor 2147483647 2147483647 r", "setText -2147483648 1 x",
                           "clearColor 2147483647 -2147483648", "clearText 1 2147483647"}) {
    m.apply(*parse_mms_line(line).command);
  }
  CHECK(m.walls == none);
  CHECK(m.colors == std::vector<char>(4, 0));
  CHECK(m.texts == std::vector<std::string>(4));
  m.apply(*parse_mms_line("setWall 1 1 S").command);
  CHECK(m.walls == std::vector<unsigned char>{0, 1, 0, 4});
  m.apply(*parse_mms_line("setColor 1 0 g").command);
  CHECK(m.colors[1] == 'g');
  m.apply(*parse_mms_line("clearAllColor").command);
  CHECK(m.colors[1] == 0);
}
