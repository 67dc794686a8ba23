#include "app/cli/floor_options.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "app/run/option_values.hpp"
#include "common/error.hpp"
#include "common/parse_number.hpp"

namespace app {

void add_boundary_option(CLI::App &cmd, std::string &boundary) {
  cmd.add_option("--boundary", boundary,
                 "XS,XE,YS,YE: an arena's floor, m (default the file's; without one, the walls' box when they "
                 "enclose the start, else the course's 17 x 17 m floor centred on the origin)");
}

maze::WorldOverrides with_arena_overrides(maze::WorldOverrides o, const std::string &boundary,
                                          double robot_radius_m) {
  o.robot_radius_m = robot_radius_m;
  if (!boundary.empty()) {
    const std::vector<double> b = parse_number_list(boundary, "--boundary", 4);
    o.boundary_m = std::array<double, 4>{b[0], b[1], b[2], b[3]};
  }
  return o;
}

CLI::Option *add_resolution_option(CLI::App &command, std::function<void(const Length &)> take,
                                   const std::string &default_text) {
  return command
      .add_option_function<std::string>(
          "--resolution",
          [take = std::move(take)](const std::string &text) {
            const std::optional<Length> length = length_of(common::trim_blanks(text));
            if (!length) throw common::InputError(fmt::format("--resolution must be a length like 0.1m or 10cm (got '{}')", text));
            if (!(length->value > 0.0) || !std::isfinite(length->value)) {
              throw common::InputError(fmt::format("--resolution must be > 0 m (got {})", text));
            }
            take(*length);
          },
          fmt::format("LENGTH: a cell's side, m, or with its unit: 0.1m, 10cm (default {})", default_text))
      ->type_name("LENGTH");
}

CLI::Option *add_resolution_option(CLI::App &command, std::optional<double> &resolution_m,
                                   const std::string &default_text) {
  return add_resolution_option(
      command, [&resolution_m](const Length &length) { resolution_m = metres(length); }, default_text);
}

}  // namespace app
