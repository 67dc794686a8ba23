// maze_mapper explain's command line; the numbers are app/course/explain.hpp's.

#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "app/cli/commands.hpp"
#include "app/cli/model_options.hpp"
#include "app/course/explain.hpp"

namespace app {

void add_explain_command(CLI::App &cli, CommandContext &context) {
  CLI::App *explain =
      cli.add_subcommand("explain", "the sensor model's numbers: p, log-odds, repeated updates");
  auto input = std::make_shared<mapping::SensorModelOptions>();
  add_model_options(*explain, *input);
  add_clamp_option(*explain, *input);
  explain->callback([&context, input] {
    std::cout << course::explain_text(*input);
    context.status = 0;
  });
}

}  // namespace app
