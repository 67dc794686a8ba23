// libFuzzer target: the room format (maze::read_room, then maze::validate_arena as the loader
// does). A file it rejects must be rejected with common::InputError (anything else escapes
// and libFuzzer reports it); an arena it accepts must be written (maze::write_room) as a
// canonical file that reads back and writes again to the very same text.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "common/error.hpp"
#include "maze/world/geometry.hpp"
#include "maze/formats/solids_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char *>(data), size);
  const std::string file = "fuzz.room";
  std::optional<maze::Arena> arena;
  try {
    arena = maze::read_room(text, file);
    if (arena->x_min_m != arena->x_max_m) maze::validate_arena(*arena);
  } catch (const common::InputError &e) {
    if (e.diagnostic().empty()) std::abort();
    return 0;
  }
  if (arena->x_min_m == arena->x_max_m) return 0;  // no boundary line: the loader's to fill
  const std::string written = maze::write_room(*arena);
  const maze::Arena back = maze::read_room(written, file);
  if (maze::write_room(back) != written) std::abort();
  return 0;
}
