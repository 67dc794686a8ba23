// Frontier exploration over a metric map (explore/metric/frontier.hpp): which cells are
// frontier, which one the robot drives to, and when a frontier cell is set aside (by itself,
// tried again once the map has progressed).

#include <doctest/doctest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "explore/metric/frontier.hpp"
#include "explore/metric/frontier_groups.hpp"
#include "explore/metric/sweep.hpp"
#include "mapping/sensor_model.hpp"
#include "plan/metric/wavefront.hpp"
#include "sensing/metric/map.hpp"

namespace {

// A map from rows, north first: '.' seen free (p 0.1), '#' seen occupied (p 0.9), ' ' never
// observed. The model and the map live as long as the fixture.
struct PictureMap {
  mapping::SensorModel model{mapping::SensorModelOptions{}};
  sensing::MetricMap map;
  explicit PictureMap(const std::vector<std::string> &rows)
      : map(sensing::metric_grid_from_cells({0.0, 0.1 * static_cast<double>(rows[0].size()), 0.0,
                                             0.1 * static_cast<double>(rows.size())},
                                            static_cast<int>(rows[0].size()), static_cast<int>(rows.size())),
            model) {
    sensing::MetricMarks marks(0.9, 0.1);
    for (std::size_t r = 0; r < rows.size(); ++r) {
      for (std::size_t i = 0; i < rows[r].size(); ++i) {
        const sensing::MetricCell c{static_cast<int>(i), static_cast<int>(rows.size() - 1 - r)};
        if (rows[r][i] == '.') marks.mark(map, c, sensing::kMetricFree);
        if (rows[r][i] == '#') marks.mark(map, c, sensing::kMetricOccupied);
      }
    }
    marks.apply(map);
  }
  std::size_t at(int i, int j) const { return map.index({i, j}); }
  // Steps from (i, j) over cells seen free.
  std::vector<std::int32_t> steps_from(int i, int j) const {
    std::vector<bool> blocked(map.size());
    for (std::size_t n = 0; n < map.size(); ++n) blocked[n] = map.unobserved_at(n) || map.probability_at(n) >= 0.5;
    return plan::steps_from({map.cells_x(), map.cells_y()}, blocked, at(i, j));
  }
};

// The flags as rows, north first: 'F' a flagged cell, '-' not.
std::vector<std::string> rows_of(const sensing::MetricMap &map, const std::vector<bool> &flags) {
  std::vector<std::string> rows;
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    std::string row;
    for (int i = 0; i < map.cells_x(); ++i) row += flags[map.index({i, j})] ? 'F' : '-';
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TEST_CASE("metric frontier: the cells never observed beside one seen free") {
  const PictureMap m({"  #   ",
                      "..#   ",
                      "...   ",
                      "..#   "});
  CHECK(rows_of(m.map, explore::frontier_cells(m.map, false)) == std::vector<std::string>{"FF----",
                                                                                   "------",
                                                                                   "---F--",
                                                                                   "------"});
}

TEST_CASE("metric frontier: with the lidar, no frontier behind a cell a beam has ended in, whatever its log-odds") {
  // A wall's face crosses the middle row: grazing beams free its cells on balance, one beam
  // ended in (2, 1). Behind it, the wall's inside (row 2) is never observed.
  PictureMap m({"      ",
                "......",
                "......"});
  sensing::MetricMarks hit(0.9, 0.1);
  hit.mark(m.map, sensing::MetricCell{2, 1}, sensing::kMetricOccupied);
  hit.apply(m.map);
  sensing::MetricMarks grazing(0.9, 0.1);
  grazing.mark(m.map, sensing::MetricCell{2, 1}, sensing::kMetricFree);
  grazing.apply(m.map);
  sensing::MetricMarks again(0.9, 0.1);
  again.mark(m.map, sensing::MetricCell{2, 1}, sensing::kMetricFree);
  again.apply(m.map);
  REQUIRE(m.map.probability_at(m.at(2, 1)) < 0.5);
  CHECK(m.map.marked_occupied_at(m.at(2, 1)));
  CHECK(!m.map.marked_occupied_at(m.at(3, 1)));
  // Any set-up: every cell of row 2 borders one seen free.
  CHECK(rows_of(m.map, explore::frontier_cells(m.map, false)) == std::vector<std::string>{"FFFFFF", "------", "------"});
  // The lidar: (2, 2) lies behind the cell the beam ended in.
  CHECK(rows_of(m.map, explore::frontier_cells(m.map, true)) == std::vector<std::string>{"FF-FFF", "------", "------"});
  // One cell at a time (what a visit's drive watches its aim with) says the same.
  CHECK(!explore::is_frontier_cell(m.map, m.at(2, 2), true));
  CHECK(explore::is_frontier_cell(m.map, m.at(2, 2), false));
  CHECK(explore::is_frontier_cell(m.map, m.at(3, 2), true));
  CHECK(!explore::is_frontier_cell(m.map, m.at(3, 1), true));  // seen free
  // A touch marks a surface too.
  m.map.observe_contact(m.at(4, 1));
  CHECK(m.map.marked_occupied_at(m.at(4, 1)));
}

TEST_CASE("metric frontier: a group no cell of which the body could cover is no target") {
  // West: open unobserved ground. East: a gap of one cell between two obstacles' faces, beside
  // cells seen occupied, so closed to the body (the planner's grown cells).
  const PictureMap m({"   ..#   ",
                      "   ..    ",
                      "   ..#   "});
  const std::vector<bool> frontier = explore::frontier_cells(m.map, false);
  REQUIRE(frontier[m.at(2, 1)]);
  REQUIRE(frontier[m.at(5, 1)]);
  std::vector<bool> closed(m.map.size(), false);
  for (int j = 0; j < 3; ++j) {
    for (int i = 4; i < 7; ++i) closed[m.at(i, j)] = true;  // the 8 neighbours of (5, 0) and (5, 2)
  }
  const explore::FrontierGroups groups = explore::group_frontier(m.map, frontier, 1, &closed);
  const auto open = static_cast<std::size_t>(groups.group_of[m.at(2, 1)]);
  const auto gap = static_cast<std::size_t>(groups.group_of[m.at(5, 1)]);
  CHECK(groups.worth_a_look(open));
  CHECK(groups.no_room[gap]);
  CHECK(!groups.worth_a_look(gap));
  const explore::FrontierSetAside aside = explore::set_aside_of(groups);
  CHECK(aside.no_room_groups == 1);
  CHECK(aside.no_room_cells == groups.cells[gap]);
  // Without the body's closed cells, no group lacks room.
  CHECK(explore::group_frontier(m.map, frontier, 1).worth_a_look(gap));
  // A cell the body cannot stand on but covers from a neighbouring cell open to it has room,
  // as the judge counts it reachable: here (6, 1), east of the gap, is open.
  closed[m.at(6, 1)] = false;
  CHECK(explore::group_frontier(m.map, frontier, 1, &closed).worth_a_look(gap));
}

TEST_CASE("metric frontier: the target is the nearest cell reached that sees a frontier cell") {
  // Two frontier cells: (3, 1) east of the room, and (0, 3) behind the wall in the north.
  const PictureMap m({" #####",
                      "#....#",
                      "#.... ",
                      "######"});
  const explore::FrontierVisits visits(m.map.size());
  const std::vector<std::int32_t> steps = m.steps_from(1, 1);
  std::vector<bool> aims = explore::frontier_cells(m.map, false);
  REQUIRE(aims[m.at(5, 1)]);
  REQUIRE(aims[m.at(0, 3)] == false);  // beside no cell seen free
  const auto t = explore::frontier_target(m.map, 0.6, aims, 5, visits, steps);
  REQUIRE(t.has_value());
  CHECK(t->aim == m.at(5, 1));
  CHECK(t->target == m.at(1, 1));  // the robot's own cell sees it along the row
  // Each visit that left it unobserved halves the view it is aimed at from: two cells, not five.
  explore::FrontierVisits visited(m.map.size());
  visited.visited(m.at(5, 1), true, {});
  const auto nearer = explore::frontier_target(m.map, 0.6, aims, 5, visited, steps);
  REQUIRE(nearer.has_value());
  CHECK(nearer->target == m.at(3, 1));
  // No cell reached: no target this round.
  const std::vector<std::int32_t> nowhere(m.map.size(), -1);
  CHECK(!explore::frontier_target(m.map, 0.6, aims, 5, visits, nowhere).has_value());
}

TEST_CASE("metric frontier: a cell left unobserved by three visits, or without a target, is set aside by itself, and "
          "tried again once the map progressed") {
  explore::FrontierVisits visits(4);
  const explore::MapProgress before{10, 20};
  visits.visited(1, true, before);
  visits.visited(1, true, before);
  CHECK(!visits.aside(1));
  visits.visited(2, false, before);  // a visit that observed its cell
  visits.visited(2, false, before);
  visits.visited(2, false, before);
  CHECK(!visits.aside(2));
  visits.visited(1, true, before);
  CHECK(visits.aside(1));
  CHECK(visits.attempts(1) == explore::kMaxFrontierAttempts);
  CHECK(!visits.aside(0));
  CHECK(!visits.aside(3));
  // Not again while the map stands still; again once it has progressed.
  CHECK(!visits.retry(1, before));
  CHECK(visits.retry(1, explore::MapProgress{11, 20}));
  CHECK(visits.retry(1, explore::MapProgress{10, 21}));
  CHECK(!visits.retry(0, explore::MapProgress{11, 21}));
  // A cell without a target in a round where none had one: set aside alone, with no visit.
  visits.set_aside(3, before);
  CHECK(visits.aside(3));
  CHECK(visits.attempts(3) == 0);
  CHECK(!visits.aside(0));
  CHECK(!visits.retry(3, before));
  CHECK(visits.retry(3, explore::MapProgress{12, 20}));
}

TEST_CASE("metric frontier: the map's progress only grows") {
  const PictureMap m({"..  ",
                      "#.  "});
  const explore::MapProgress first = explore::progress_of(m.map, 3, {});
  CHECK(first == explore::MapProgress{4, 3});
  // Fewer cells free for planning than before: the high-water mark stays.
  CHECK(explore::progress_of(m.map, 2, first) == first);
  CHECK(explore::progress_of(m.map, 5, first) == explore::MapProgress{4, 5});
}

TEST_CASE("metric frontier groups: a small group and an obstacle's inside seen through a gap are no targets") {
  // West: an open edge of five frontier cells (column 1, beside the seen free column 0).
  // East: a box, its inside never observed, seen through a gap of one cell in its west face.
  const PictureMap m({".        ##### ",
                      ".       .#   # ",
                      ".       ..   # ",
                      ".       .#   # ",
                      ".       .##### "});
  const std::vector<bool> frontier = explore::frontier_cells(m.map, false);
  const explore::FrontierGroups groups = explore::group_frontier(m.map, frontier, 3);
  REQUIRE(frontier[m.at(1, 2)]);
  REQUIRE(frontier[m.at(10, 2)]);
  const auto open = static_cast<std::size_t>(groups.group_of[m.at(1, 2)]);
  const auto gap = static_cast<std::size_t>(groups.group_of[m.at(10, 2)]);
  CHECK(groups.cells[open] >= 5);
  CHECK(groups.worth_a_look(open));
  CHECK(groups.cells[gap] == 1);
  CHECK(groups.small[gap]);
  CHECK(!groups.worth_a_look(gap));
  const std::vector<bool> looked = explore::cells_worth_a_look(groups);
  CHECK(looked[m.at(1, 2)]);
  CHECK(!looked[m.at(10, 2)]);
  const explore::FrontierSetAside aside = explore::set_aside_of(groups);
  CHECK(aside.small_cells >= 1);
  // With a minimum of one cell the gap is no longer small, but what lies behind it is the
  // box's inside, whose whole frontier is that cell: enclosed at a minimum of two.
  CHECK(explore::group_frontier(m.map, frontier, 1).worth_a_look(gap));
  const explore::FrontierGroups two = explore::group_frontier(m.map, frontier, 2);
  CHECK(two.small[gap]);
  CHECK(two.enclosed[gap]);
}

TEST_CASE("metric frontier: a farther target that looks at a larger group wins over a nearer one only by its gain") {
  // Row 0 free; a frontier cell north of (1, 0) and one north of (3, 0).
  const PictureMap m({"# ## #",
                      "......"});
  const std::vector<bool> aims = explore::frontier_cells(m.map, false);
  REQUIRE(aims[m.at(1, 1)]);
  REQUIRE(aims[m.at(4, 1)]);
  const explore::FrontierVisits visits(m.map.size());
  const std::vector<std::int32_t> steps = m.steps_from(0, 0);
  std::vector<std::int32_t> gain(m.map.size(), 0);
  gain[m.at(1, 1)] = 1;
  gain[m.at(4, 1)] = 1;
  const auto nearest = explore::frontier_target(m.map, 0.6, aims, 1, visits, steps, &gain);
  REQUIRE(nearest.has_value());
  CHECK(nearest->aim == m.at(1, 1));
  // (4, 0) is 3 steps farther than (1, 0), a cost of 9: a gain 8 greater loses, 10 greater wins.
  gain[m.at(4, 1)] = 9;
  CHECK(explore::frontier_target(m.map, 0.6, aims, 1, visits, steps, &gain)->aim == m.at(1, 1));
  gain[m.at(4, 1)] = 11;
  CHECK(explore::frontier_target(m.map, 0.6, aims, 1, visits, steps, &gain)->aim == m.at(4, 1));
}

TEST_CASE("metric sweep: a leg's rest observes nothing only over ground seen and a line seen free") {
  // A leg along the middle row from (1, 1) east to (5, 1), for a body of radius 0.09 m (it
  // overlaps the rows either side by 0.04 m).
  const auto adds_nothing = [](const std::vector<std::string> &rows) {
    const PictureMap m(rows);
    const explore::BodyView view{
        m.map, 0.09, [&](std::size_t n) { return !m.map.unobserved_at(n) && m.map.probability_at(n) >= 0.5; },
        [&](std::size_t n) { return !m.map.unobserved_at(n) && m.map.probability_at(n) < 0.5; }};
    return explore::body_path_adds_nothing(view, m.map.centre_of({1, 1}), m.map.centre_of({5, 1}));
  };
  CHECK(adds_nothing({".......", ".......", "......."}));
  CHECK(adds_nothing({"...#...", ".......", "......."}));   // seen occupied beside the line: nothing to learn
  CHECK(!adds_nothing({"... ...", ".......", "......."}));  // unobserved under the body's side
  CHECK(!adds_nothing({".......", "...#...", "......."}));  // on the line: the body may find it open
  CHECK(!adds_nothing({".......", "..... .", "......."}));  // the leg's end unobserved
}
