// libFuzzer target: maze::read_xml (see fuzz_world.hpp for what counts as a failure). Written
// back at its own origin, so that reading it again gives the very same maze.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_world.hpp"
#include "maze/formats/xml_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  return fuzz::read_world_bytes(
      data, size, [](std::string_view text, const std::string &file) { return maze::read_xml(text, file); },
      [](const maze::Maze &m) { return maze::write_xml_keeping_origin(m); });
}
