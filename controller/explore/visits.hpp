#pragma once
// Which cells the robot has visited and the last heading it had in each (what the map
// shows as an arrow at the cell's centre).

#include <cstdint>
#include <optional>
#include <vector>

#include "mapping/grid_types.hpp"

namespace explore {

class Visits {
 public:
  Visits(int width_cells, int height_cells);

  int width() const { return width_; }
  int height() const { return height_; }
  bool contains(mapping::Cell c) const { return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_; }

  // Marks c visited (c inside) and remembers h as its last heading.
  void record(mapping::Cell c, mapping::Heading h);

  bool visited(mapping::Cell c) const { return heading_plus_one_[flat(c)] != 0; }
  std::optional<mapping::Heading> heading(mapping::Cell c) const;
  int count() const { return count_; }

 private:
  std::size_t flat(mapping::Cell c) const {
    return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(c.x);
  }
  int width_;
  int height_;
  int count_ = 0;
  std::vector<std::uint8_t> heading_plus_one_;  // 0 = not visited
};

}  // namespace explore
