// libFuzzer target: maze::read_num (see fuzz_world.hpp for what counts as a failure).

#include <cstddef>
#include <cstdint>

#include "fuzz_world.hpp"
#include "maze/formats/num_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  return fuzz::read_world_bytes(data, size, maze::read_num, maze::write_num);
}
