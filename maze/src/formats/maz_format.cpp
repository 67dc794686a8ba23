#include "maze/formats/maz_format.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "common/error.hpp"
#include "maze/world/validate.hpp"

namespace maze {
namespace {

constexpr unsigned char kBits[] = {0x01, 0x02, 0x04, 0x08};  // north, east, south, west

std::size_t byte_of(Cell c) { return static_cast<std::size_t>(c.x * kMazCells + c.y); }

common::SourceLocation at_byte(const std::string &file, std::size_t byte) {
  return common::SourceLocation{file, 1, static_cast<int>(byte) + 1};
}

}  // namespace

Maze read_maz(std::string_view text, const std::string &file) {
  if (text.size() != kMazBytes) {
    throw common::InputError(common::SourceLocation{file, 0, 0},
                             fmt::format("a binary maze (.maz) is {} bytes, one a cell of a 16 x 16 maze; this file has {}",
                                         kMazBytes, text.size()));
  }
  RawMaze raw;
  raw.resize(kMazCells, kMazCells);
  for (std::size_t i = 0; i < kMazBytes; ++i) {
    const auto value = static_cast<unsigned char>(text[i]);
    const Cell c{static_cast<int>(i) / kMazCells, static_cast<int>(i) % kMazCells};
    if (value > 0x0F) {
      throw common::InputError(at_byte(file, i), fmt::format("byte {} (cell ({},{})) is 0x{:02X}: a cell's byte holds "
                                                             "only the wall bits 0x01 N, 0x02 E, 0x04 S, 0x08 W",
                                                             i + 1, c.x, c.y, value));
    }
    for (const Side s : kSides) raw.set(c, s, (value & kBits[static_cast<int>(s)]) != 0);
  }
  for (const int x : {kMazCells / 2 - 1, kMazCells / 2}) {
    for (const int y : {kMazCells / 2 - 1, kMazCells / 2}) {
      raw.goals.push_back({x, y});
      raw.goal_where.push_back(common::SourceLocation{file, 0, 0});
    }
  }
  raw.where = [file](Cell c, Side) { return at_byte(file, byte_of(c)); };
  return build_maze(raw);
}

std::string write_maz(const Maze &maze) {
  if (maze.width() != kMazCells || maze.height() != kMazCells) {
    throw common::InputError(fmt::format("a binary maze (.maz) holds a 16 x 16 maze; this one is {}x{}", maze.width(),
                                         maze.height()));
  }
  std::string bytes(kMazBytes, '\0');
  for (int x = 0; x < kMazCells; ++x) {
    for (int y = 0; y < kMazCells; ++y) {
      unsigned char value = 0;
      for (const Side s : kSides) {
        if (maze.has_wall({x, y}, s)) value = static_cast<unsigned char>(value | kBits[static_cast<int>(s)]);
      }
      bytes[byte_of({x, y})] = static_cast<char>(value);
    }
  }
  return bytes;
}

}  // namespace maze
