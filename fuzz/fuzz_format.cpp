// libFuzzer target: telling a world file's format (maze::FormatDetector). The first byte sets
// the size of the pieces the rest arrives in; the format told, or the error, must be the
// same as for the whole text at once (anything but common::InputError escapes and libFuzzer
// reports it). A small limit (4 KiB) puts the "no meaningful line in the first ..." refusal
// within the inputs' reach.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "common/error.hpp"
#include "maze/world/format_detector.hpp"

namespace {

constexpr std::size_t kWithin = 4096;

// The format told, or the error's diagnostic.
std::string told_at_once(std::string_view text) {
  try {
    const std::optional<maze::Format> format = maze::FormatDetector("f", kWithin).look(text, true);
    if (!format) std::abort();  // at the end the bytes always tell
    return std::to_string(static_cast<int>(*format));
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
}

std::string told_in_pieces(std::string_view text, std::size_t piece) {
  maze::FormatDetector detector("f", kWithin);
  try {
    for (std::size_t n = std::min(piece, text.size());; n = std::min(n + piece, text.size())) {
      const bool at_end = n == text.size();
      if (const std::optional<maze::Format> format = detector.look(text.substr(0, n), at_end)) {
        return std::to_string(static_cast<int>(*format));
      }
      if (at_end) std::abort();
    }
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t piece = 1 + data[0] % 32;
  const std::string_view text(reinterpret_cast<const char *>(data) + 1, size - 1);
  if (told_in_pieces(text, piece) != told_at_once(text)) std::abort();
  return 0;
}
