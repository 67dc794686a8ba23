#pragma once
// The body every maze-reader fuzz target shares: read the bytes with one reader; a file it
// rejects must be rejected with common::InputError (anything else escapes and libFuzzer
// reports it), and a maze it accepts must survive writing and reading back unchanged.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "common/error.hpp"
#include "maze/world/maze.hpp"
#include "maze/world/world.hpp"

namespace fuzz {

template <typename Reader, typename Writer>
int read_world_bytes(const std::uint8_t *data, std::size_t size, Reader read, Writer write) {
  const std::string_view text(reinterpret_cast<const char *>(data), size);
  const std::string file = "fuzz";
  std::optional<maze::Maze> maze;
  try {
    maze = read(text, file);
  } catch (const common::InputError &e) {
    if (e.diagnostic().empty()) std::abort();
    return 0;
  }
  const std::string written = write(*maze);
  if (read(written, file) != *maze) std::abort();
  if (maze::read_world(written, file) != *maze) std::abort();
  return 0;
}

}  // namespace fuzz
