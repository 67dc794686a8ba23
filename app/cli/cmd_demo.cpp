// maze_mapper demo: the list of demos and demo 1d's command line; the exercise itself is
// app/course/demo_1d_exercise.hpp.

#include <algorithm>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/cli/floor_options.hpp"
#include "app/cli/cli_options.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/demo_commands.hpp"
#include "app/cli/model_options.hpp"
#include "app/course/demo_1d_exercise.hpp"
#include "common/standard_streams.hpp"

namespace app {
namespace {

// `demo` alone: the demos, one a line, as `robot` alone lists the robots.
void list_demos(const CLI::App &demo, std::ostream &out) {
  std::size_t width = 0;
  const auto all = [](const CLI::App *) { return true; };
  for (const CLI::App *d : demo.get_subcommands(all)) width = std::max(width, d->get_name().size());
  for (const CLI::App *d : demo.get_subcommands(all)) {
    out << fmt::format("{:<{}}  {}\n", d->get_name(), width, d->get_description());
  }
}

// demo 1d's --resolution in its cm; a bare number was cm before --resolution was declared once
// (in metres), and is read so for one release, with a warning.
double demo_1d_spacing_cm(const Length &spacing) {
  if (spacing.unit == LengthUnit::none) {
    common::print_stderr("{}\n", old_spelling_warning(fmt::format("--resolution {}", spacing.value),
                                                    fmt::format("--resolution {}cm", spacing.value)));
  }
  return centimetres(spacing, LengthUnit::cm);
}

void add_demo_1d(CLI::App &demo, CommandContext &context) {
  CLI::App *one_d = demo.add_subcommand("1d", "the textbook 1-D log-odds exercise");
  auto input = std::make_shared<course::Demo1dInput>();
  course::Demo1dOptions &o = input->options;
  CLI::Option *measurements = one_d->add_option(
      "--measurements", input->measurements,
      fmt::format("comma-separated ranges in cm (default {})", fmt::join(o.measurements_cm, ",")));
  add_model_options(*one_d, o.model);
  one_d->add_option("--behind", o.behind_cm, fmt::format("occupied stretch behind a hit, cm (default {})", o.behind_cm));
  add_resolution_option(*one_d, [&o](const Length &spacing) { o.resolution_cm = demo_1d_spacing_cm(spacing); },
                        fmt::format("{}cm; a number without its unit is still cm in this release, with a warning",
                                    o.resolution_cm));
  one_d->add_option("--length", o.length_cm, fmt::format("position of the last cell, cm (default {})", o.length_cm));
  one_d->add_option("--order", input->order, "integration order: given or shuffle (default given)");
  add_seed_option(*one_d, input->seed, "the shuffle");
  one_d->add_option("--svg", input->svg_path, "FILE: also write the plot as an SVG file");
  one_d->callback([&context, input, measurements] {
    input->measurements_given = measurements->count() > 0;
    const course::Demo1dOutput output = course::run_demo_1d(*input);
    std::cout << output.text;
    context.status = output.status;
  });
}

}  // namespace

void add_demo_command(CLI::App &cli, CommandContext &context) {
  CLI::App *demo = cli.add_subcommand("demo", "teaching demos of the log-odds mapping; alone, the list of demos");
  demo->require_subcommand(0, 1);
  add_demo_1d(*demo, context);
  add_demo_pie(*demo, context);
  add_demo_cone(*demo, context);
  add_demo_trilaterate(*demo, context);
  add_demo_localize(*demo, context);
  demo->callback([demo, &context] {
    if (!demo->get_subcommands().empty()) return;
    list_demos(*demo, std::cout);
    context.status = 0;
  });
}

}  // namespace app
