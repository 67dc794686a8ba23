// libFuzzer target: a robot profile file (`--robot FILE.json`, app::profile_from_json). A file
// it rejects must be rejected with common::InputError (anything else escapes and libFuzzer
// reports it: nlohmann's own exceptions, a crash, a sanitizer report); a profile it accepts
// must print (`maze_mapper robot NAME`) and read back to the very same profile.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "app/run/profile_json.hpp"
#include "common/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char *>(data), size);
  const std::string file = "fuzz.json";
  std::optional<maze::sim::RobotProfile> profile;
  try {
    profile = app::profile_from_json(text, file);
  } catch (const common::InputError &e) {
    if (e.diagnostic().empty()) std::abort();
    return 0;
  }
  const std::string printed = app::profile_to_json(*profile);
  if (app::profile_from_json(printed, file) != *profile) std::abort();
  return 0;
}
