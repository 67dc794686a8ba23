#pragma once
// Exploration strategies: deterministic, pure logic over the known walls, the cells visited,
// the current cell and heading, and the maze size. Each answers "the heading to move next,
// or done". Walls are what the robot knows (read from its grid), never the truth; a side
// leading out of the W x H grid is always a wall; a move is only made through a side known
// to be open (floodfill also through unknown sides, as micromouse flooding assumes).
//
//   dfs        depth-first with backtracking (default). Neighbours tried relative to the
//              heading: ahead, right, left, back. Backtracks along the path it came by.
//   frontier   to the nearest unvisited cell through known openings (breadth-first search
//              over visited cells; neighbours expanded N, E, S, W, so ties go to the cell
//              found first in that order); follows the planned path, re-plans on arrival or
//              when a side on it turns out closed.
//   left-wall  keep the left hand on the wall: left, ahead, right, back.
//   right-wall right, ahead, left, back.
//   floodfill  micromouse search: flooding to the goal, then on until the known path from
//              the start to the goal is proven shortest (explore/shortest_path.hpp). Flooding:
//              distances to the target cells by breadth-first search, unknown sides taken as
//              open; move to the neighbour one step nearer (ahead, right, left, back on
//              ties); re-flooded before every move. The targets are the goal cells until one
//              is reached, then the cells not yet visited whose unknown side lies on an
//              optimistic shortest path from the start (the first N, E, S, W tie).
//
// Ending: dfs and frontier when no known-open unvisited cell remains next to a visited one
// (every reachable cell visited); wall followers when back at the start about to repeat
// their first move (a full circuit), or when they arrive in a cell with a heading they
// arrived in it with before and no new cell visited since: walls learned on the way made a
// circuit that misses the start, and it would repeat for ever; floodfill once the shortest
// path is proven (proven()), or unproven when no goal is reachable through the sides not
// known to be walls or an unknown side on the optimistic path belongs to a cell already
// visited.
//
// Cost per move: dfs O(1). frontier O(cells searched), bounded by the visited cells within
// the distance of the nearest unvisited one, and only when it re-plans. floodfill O(cells)
// per move (the flood stops once it reaches the robot's cell) - acceptable at the maze sizes
// floodfill is meant for. Buffers are allocated once, O(W * H).

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "mapping/grid_types.hpp"
#include "mapping/walls.hpp"

namespace explore {

// Every exploration strategy, of both controllers: the cell controller's on a maze's cells
// (above) and the metric controller's in metres (robot/metric/controller.hpp: waypoints,
// wavefront, frontier, wander). frontier is one word with a variant in each.
enum class StrategyKind { dfs, frontier, left_wall, right_wall, floodfill, waypoints, wavefront, wander };

// Where a strategy explores: on a maze's cells, in metres, or both (a variant of each).
enum class StrategySpace { cells, metres };

// One row of the one strategy table: its --strategy word and the spaces it has a variant in.
struct StrategyRow {
  StrategyKind kind;
  std::string_view name;
  bool on_cells;
  bool in_metres;
};

// The table, in the order help and messages list the strategies.
std::span<const StrategyRow> strategy_table();

std::string_view to_string(StrategyKind kind);
// Whether `kind` has a variant in `space`.
bool explores_in(StrategyKind kind, StrategySpace space);
// "dfs, frontier, left-wall, right-wall or floodfill": the words of the strategies of `space`.
std::string strategy_names(StrategySpace space);
// The strategy of `space` named `name` ("dfs", "left-wall", ...; "waypoints", ... in metres);
// throws common::InputError naming --strategy and the choices otherwise.
StrategyKind parse_strategy(std::string_view name, StrategySpace space = StrategySpace::cells);

// What the robot knows about side h of cell c (c inside the grid).
using WallQuery = std::function<mapping::SideState(mapping::Cell, mapping::Heading)>;

struct ExplorerOptions {
  StrategyKind kind = StrategyKind::dfs;
  int width_cells = 0;
  int height_cells = 0;
  mapping::Cell start;
  std::vector<mapping::Cell> goals;  // floodfill's targets (micromouse knowledge, not walls)
};

// Throws common::InputError when the strategy has no cell variant, the size is not positive, the start is outside, or
// floodfill has no goal or a goal outside the maze.
void validate(const ExplorerOptions &options);

class Explorer {
 public:
  explicit Explorer(const ExplorerOptions &options);

  // The robot stands at `current` facing `heading`, having scanned it. Records the cell as
  // visited, then answers the heading of the next move (to an adjacent cell), or nothing
  // when the strategy is done. Call once per cell the robot arrives in, start included.
  std::optional<mapping::Heading> next(mapping::Cell current, mapping::Heading heading,
                                       const WallQuery &walls);

  // Cells recorded as visited so far, and unvisited cells known to be reachable.
  int visited_count() const { return visited_count_; }
  int frontier_count() const { return frontier_count_; }
  // floodfill: a goal cell was reached, and the search ended with the shortest path proven.
  bool reached_goal() const { return reached_goal_; }
  bool proven() const { return proven_; }

 private:
  enum class Mark : std::uint8_t { unseen, frontier, visited };

  std::size_t flat(mapping::Cell c) const {
    return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(options_.width_cells) +
           static_cast<std::size_t>(c.x);
  }
  bool inside(mapping::Cell c) const {
    return c.x >= 0 && c.y >= 0 && c.x < options_.width_cells && c.y < options_.height_cells;
  }
  bool open(const WallQuery &walls, mapping::Cell c, mapping::Heading h) const;
  void visit(mapping::Cell c, const WallQuery &walls);

  std::optional<mapping::Heading> next_dfs(mapping::Cell c, mapping::Heading h, const WallQuery &walls);
  std::optional<mapping::Heading> next_frontier(mapping::Cell c, const WallQuery &walls);
  std::optional<mapping::Heading> next_follower(mapping::Cell c, mapping::Heading h, const WallQuery &walls);
  std::optional<mapping::Heading> next_floodfill(mapping::Cell c, mapping::Heading h, const WallQuery &walls);
  bool plan_frontier(mapping::Cell c, const WallQuery &walls);
  // Marks in target_ the unvisited cells with an unknown side on the optimistic path; false
  // when there is none (or no such path).
  bool mark_unknown_on_optimistic_path(const WallQuery &walls);
  std::optional<mapping::Heading> flood_towards(const std::vector<std::uint8_t> &targets, mapping::Cell c,
                                                mapping::Heading h, const WallQuery &walls);

  ExplorerOptions options_;
  std::vector<Mark> marks_;
  int visited_count_ = 0;
  int frontier_count_ = 0;
  bool started_ = false;

  std::vector<mapping::Cell> stack_;               // dfs: the path from the start
  std::vector<mapping::Heading> plan_;             // frontier: remaining moves, last first
  std::optional<mapping::Heading> first_move_;     // followers
  // followers: per cell and arrival heading, 1 + visited_count_ at the last such arrival.
  std::vector<std::int32_t> arrivals_;
  std::vector<std::uint8_t> goal_;                 // floodfill: 1 on goal cells
  std::vector<std::uint8_t> target_;               // floodfill proving: 1 on cells to visit
  bool reached_goal_ = false;
  bool proven_ = false;

  // Breadth-first search buffers, allocated once; a cell is seen when seen_[i] == epoch_.
  std::vector<std::uint32_t> seen_;
  std::vector<std::int32_t> distance_;
  std::vector<mapping::Heading> arrived_by_;
  std::vector<mapping::Cell> queue_;
  std::uint32_t epoch_ = 0;
  void new_search();
};

}  // namespace explore
