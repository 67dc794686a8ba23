#include "explore/strategies.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "explore/shortest_path.hpp"
#include "explore/visits.hpp"

namespace explore {

using mapping::Cell;
using mapping::Heading;
using mapping::SideState;

namespace {

// Relative preference orders.
std::array<Heading, 4> ahead_right_left_back(Heading h) {
  return {h, mapping::turned_right(h), mapping::turned_left(h), mapping::opposite(h)};
}
std::array<Heading, 4> left_hand(Heading h) {
  return {mapping::turned_left(h), h, mapping::turned_right(h), mapping::opposite(h)};
}
std::array<Heading, 4> right_hand(Heading h) {
  return {mapping::turned_right(h), h, mapping::turned_left(h), mapping::opposite(h)};
}

// The heading from a cell to an adjacent one.
Heading direction(Cell from, Cell to) {
  if (to.x > from.x) return Heading::east;
  if (to.x < from.x) return Heading::west;
  if (to.y > from.y) return Heading::north;
  assert(to.y < from.y);
  return Heading::south;
}

}  // namespace

// ---- Visits ----

Visits::Visits(int width_cells, int height_cells)
    : width_(width_cells),
      height_(height_cells),
      heading_plus_one_(static_cast<std::size_t>(width_cells) * static_cast<std::size_t>(height_cells), 0) {
  assert(width_cells > 0 && height_cells > 0);
}

void Visits::record(Cell c, Heading h) {
  assert(contains(c));
  auto &slot = heading_plus_one_[flat(c)];
  if (slot == 0) ++count_;
  slot = static_cast<std::uint8_t>(static_cast<int>(h) + 1);
}

std::optional<Heading> Visits::heading(Cell c) const {
  const auto v = heading_plus_one_[flat(c)];
  if (v == 0) return std::nullopt;
  return static_cast<Heading>(v - 1);
}

// ---- names and options ----

std::span<const StrategyRow> strategy_table() {
  static constexpr StrategyRow kStrategies[] = {
      // In this order each space's words read as its help has always listed them.
      {StrategyKind::waypoints, "waypoints", false, true},
      {StrategyKind::wavefront, "wavefront", false, true},
      {StrategyKind::dfs, "dfs", true, false},
      {StrategyKind::frontier, "frontier", true, true},
      {StrategyKind::left_wall, "left-wall", true, false},
      {StrategyKind::right_wall, "right-wall", true, false},
      {StrategyKind::floodfill, "floodfill", true, false},
      {StrategyKind::wander, "wander", false, true},
  };
  return kStrategies;
}

namespace {

const StrategyRow &row_of(StrategyKind kind) {
  for (const StrategyRow &row : strategy_table()) {
    if (row.kind == kind) return row;
  }
  assert(false && "a strategy without a row");
  return strategy_table().front();
}

bool in_space(const StrategyRow &row, StrategySpace space) {
  return space == StrategySpace::cells ? row.on_cells : row.in_metres;
}

}  // namespace

std::string_view to_string(StrategyKind kind) { return row_of(kind).name; }

bool explores_in(StrategyKind kind, StrategySpace space) { return in_space(row_of(kind), space); }

std::string strategy_names(StrategySpace space) {
  std::vector<std::string_view> names;
  for (const StrategyRow &row : strategy_table()) {
    if (in_space(row, space)) names.push_back(row.name);
  }
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += i + 1 == names.size() ? " or " : ", ";
    text += names[i];
  }
  return text;
}

StrategyKind parse_strategy(std::string_view name, StrategySpace space) {
  for (const StrategyRow &row : strategy_table()) {
    if (row.name == name && in_space(row, space)) return row.kind;
  }
  if (space == StrategySpace::metres) {
    throw common::InputError(
        fmt::format("--strategy must be {} in a room (got '{}')", strategy_names(StrategySpace::metres), name));
  }
  throw common::InputError(fmt::format("unknown --strategy '{}' (choose {})", name, strategy_names(StrategySpace::cells)));
}

void validate(const ExplorerOptions &o) {
  if (!explores_in(o.kind, StrategySpace::cells)) {
    throw common::InputError(fmt::format("--strategy {} explores in metres, not on a maze's cells (maze_mapper room)",
                                         to_string(o.kind)));
  }
  if (o.width_cells < 1 || o.height_cells < 1) {
    throw common::InputError(
        fmt::format("maze size must be positive (got {}x{})", o.width_cells, o.height_cells));
  }
  const auto inside = [&](Cell c) {
    return c.x >= 0 && c.y >= 0 && c.x < o.width_cells && c.y < o.height_cells;
  };
  if (!inside(o.start)) {
    throw common::InputError(fmt::format("start cell ({},{}) is outside the {}x{} maze",
                                         o.start.x, o.start.y, o.width_cells, o.height_cells));
  }
  for (const Cell g : o.goals) {
    if (!inside(g)) {
      throw common::InputError(fmt::format("goal cell ({},{}) is outside the {}x{} maze", g.x,
                                           g.y, o.width_cells, o.height_cells));
    }
  }
  if (o.kind == StrategyKind::floodfill && o.goals.empty()) {
    throw common::InputError(
        "--strategy floodfill needs a goal cell (the world has none: no G in a text map, none in a num file): give "
        "--goal X,Y, or --goal centre for the maze's centre cells");
  }
}

// ---- Explorer ----

Explorer::Explorer(const ExplorerOptions &options) : options_(options) {
  validate(options_);
  const auto cells = static_cast<std::size_t>(options_.width_cells) *
                     static_cast<std::size_t>(options_.height_cells);
  marks_.assign(cells, Mark::unseen);
  if (options_.kind == StrategyKind::frontier || options_.kind == StrategyKind::floodfill) {
    seen_.assign(cells, 0);
    distance_.assign(cells, 0);
    arrived_by_.assign(cells, Heading::north);
    queue_.reserve(cells);
  }
  if (options_.kind == StrategyKind::left_wall || options_.kind == StrategyKind::right_wall) {
    arrivals_.assign(cells * std::size(mapping::kHeadings), 0);
  }
  if (options_.kind == StrategyKind::floodfill) {
    goal_.assign(cells, 0);
    for (const Cell g : options_.goals) goal_[flat(g)] = 1;
    target_.assign(cells, 0);
  }
}

bool Explorer::open(const WallQuery &walls, Cell c, Heading h) const {
  return inside(mapping::neighbour(c, h)) && walls(c, h) == SideState::open;
}

void Explorer::visit(Cell c, const WallQuery &walls) {
  Mark &m = marks_[flat(c)];
  if (m == Mark::visited) return;
  if (m == Mark::frontier) --frontier_count_;
  m = Mark::visited;
  ++visited_count_;
  for (const Heading h : mapping::kHeadings) {
    if (!open(walls, c, h)) continue;
    Mark &n = marks_[flat(mapping::neighbour(c, h))];
    if (n != Mark::unseen) continue;
    n = Mark::frontier;
    ++frontier_count_;
  }
}

std::optional<Heading> Explorer::next(Cell current, Heading heading, const WallQuery &walls) {
  assert(inside(current));
  if (!started_) {
    started_ = true;
    stack_.push_back(current);
  }
  visit(current, walls);
  switch (options_.kind) {
    case StrategyKind::dfs: return next_dfs(current, heading, walls);
    case StrategyKind::frontier: return next_frontier(current, walls);
    case StrategyKind::left_wall:
    case StrategyKind::right_wall: return next_follower(current, heading, walls);
    case StrategyKind::floodfill: return next_floodfill(current, heading, walls);
    case StrategyKind::waypoints:
    case StrategyKind::wavefront:
    case StrategyKind::wander: break;  // no cell variant: validate() refuses them
  }
  return std::nullopt;
}

std::optional<Heading> Explorer::next_dfs(Cell c, Heading h, const WallQuery &walls) {
  assert(!stack_.empty() && stack_.back() == c);
  if (frontier_count_ == 0) return std::nullopt;
  for (const Heading d : ahead_right_left_back(h)) {
    if (!open(walls, c, d)) continue;
    const Cell n = mapping::neighbour(c, d);
    if (marks_[flat(n)] == Mark::visited) continue;
    stack_.push_back(n);
    return d;
  }
  stack_.pop_back();
  if (stack_.empty()) return std::nullopt;
  return direction(c, stack_.back());
}

void Explorer::new_search() {
  if (++epoch_ == 0) {
    std::fill(seen_.begin(), seen_.end(), 0);
    epoch_ = 1;
  }
  queue_.clear();
}

std::optional<Heading> Explorer::next_frontier(Cell c, const WallQuery &walls) {
  if (frontier_count_ == 0) return std::nullopt;
  const bool still_good = !plan_.empty() && open(walls, c, plan_.back());
  if (!still_good && !plan_frontier(c, walls)) return std::nullopt;
  const Heading d = plan_.back();
  plan_.pop_back();
  return d;
}

bool Explorer::plan_frontier(Cell c, const WallQuery &walls) {
  plan_.clear();
  new_search();
  seen_[flat(c)] = epoch_;
  queue_.push_back(c);
  for (std::size_t head = 0; head < queue_.size(); ++head) {
    const Cell u = queue_[head];
    if (marks_[flat(u)] != Mark::visited) {
      for (Cell v = u; v != c; v = mapping::neighbour(v, mapping::opposite(arrived_by_[flat(v)]))) {
        plan_.push_back(arrived_by_[flat(v)]);
      }
      return true;
    }
    for (const Heading h : mapping::kHeadings) {
      if (!open(walls, u, h)) continue;
      const Cell v = mapping::neighbour(u, h);
      if (seen_[flat(v)] == epoch_) continue;
      seen_[flat(v)] = epoch_;
      arrived_by_[flat(v)] = h;
      queue_.push_back(v);
    }
  }
  return false;
}

std::optional<Heading> Explorer::next_follower(Cell c, Heading h, const WallQuery &walls) {
  std::int32_t &arrived = arrivals_[flat(c) * std::size(mapping::kHeadings) + static_cast<std::size_t>(h)];
  if (arrived == visited_count_ + 1) return std::nullopt;  // circling: nothing new since the last time here
  arrived = visited_count_ + 1;
  const auto order = options_.kind == StrategyKind::left_wall ? left_hand(h) : right_hand(h);
  for (const Heading d : order) {
    if (!open(walls, c, d)) continue;
    if (first_move_ && c == options_.start && d == *first_move_) return std::nullopt;
    if (!first_move_) first_move_ = d;
    return d;
  }
  return std::nullopt;
}

std::optional<Heading> Explorer::next_floodfill(Cell c, Heading h, const WallQuery &walls) {
  if (!reached_goal_) {
    if (goal_[flat(c)] == 0) return flood_towards(goal_, c, h, walls);
    reached_goal_ = true;
  }
  if (prove_shortest_path(options_, walls).proven()) {
    proven_ = true;
    return std::nullopt;
  }
  if (!mark_unknown_on_optimistic_path(walls)) return std::nullopt;
  return flood_towards(target_, c, h, walls);
}

bool Explorer::mark_unknown_on_optimistic_path(const WallQuery &walls) {
  const MazeSize size{options_.width_cells, options_.height_cells};
  const auto route = shortest_route(size, options_.start, options_.goals, walls, UnknownSides::open);
  if (!route) return false;
  std::fill(target_.begin(), target_.end(), 0);
  bool any = false;
  Cell u = options_.start;
  for (const Heading d : *route) {
    if (walls(u, d) == SideState::unknown && marks_[flat(u)] != Mark::visited) {
      target_[flat(u)] = 1;
      any = true;
    }
    u = mapping::neighbour(u, d);
  }
  return any;
}

std::optional<Heading> Explorer::flood_towards(const std::vector<std::uint8_t> &targets, Cell c, Heading h,
                                               const WallQuery &walls) {
  // Flood from the targets over sides not known to be walls, until the robot's cell is reached.
  new_search();
  for (std::size_t i = 0; i < targets.size(); ++i) {
    if (targets[i] == 0) continue;
    const Cell t{static_cast<int>(i % static_cast<std::size_t>(options_.width_cells)),
                 static_cast<int>(i / static_cast<std::size_t>(options_.width_cells))};
    seen_[i] = epoch_;
    distance_[i] = 0;
    queue_.push_back(t);
  }
  bool reached = seen_[flat(c)] == epoch_;
  for (std::size_t head = 0; head < queue_.size() && !reached; ++head) {
    const Cell u = queue_[head];
    for (const Heading d : mapping::kHeadings) {
      const Cell v = mapping::neighbour(u, d);
      if (!inside(v) || seen_[flat(v)] == epoch_ || walls(u, d) == SideState::wall) continue;
      seen_[flat(v)] = epoch_;
      distance_[flat(v)] = distance_[flat(u)] + 1;
      queue_.push_back(v);
      reached = reached || v == c;
    }
  }
  if (!reached || distance_[flat(c)] == 0) return std::nullopt;
  const std::int32_t want = distance_[flat(c)] - 1;
  for (const Heading d : ahead_right_left_back(h)) {
    const Cell n = mapping::neighbour(c, d);
    if (!inside(n) || walls(c, d) == SideState::wall) continue;
    if (seen_[flat(n)] == epoch_ && distance_[flat(n)] == want) return d;
  }
  assert(false && "a flooded cell always has a neighbour one step nearer");
  return std::nullopt;
}

}  // namespace explore
