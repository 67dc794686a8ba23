// The world subcommands: worlds, show, convert, generate.

#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "app/cli/floor_options.hpp"
#include "app/cli/cli_options.hpp"
#include "app/cli/commands.hpp"
#include "app/report/webots_export.hpp"
#include "app/run/option_values.hpp"
#include "app/run/shipped_worlds.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/parse_number.hpp"
#include "common/standard_streams.hpp"
#include "maze/formats/geometry_text.hpp"
#include "maze/generate/generator.hpp"
#include "maze/generate/solids_generator.hpp"
#include "maze/formats/solids_format.hpp"
#include "maze/world/world_files.hpp"
#include "maze/formats/text_map.hpp"
#include "maze/world/world.hpp"
#include "maze/formats/xml_format.hpp"

namespace app {

maze::World load_world_reporting(const std::string &path, const maze::WorldOverrides &overrides) {
  maze::World world = maze::load_world(path, overrides);
  for (const std::string &warning : world.warnings) common::print_stderr("{}\n", warning);
  return world;
}

namespace {

// One shipped world's line of `worlds`: its file name, whether it is a grid maze or an arena
// (a room in metres), and its size; a file that does not load says why.
std::string shipped_world_line(const std::filesystem::path &file) {
  const std::string name = file.filename().string();
  try {
    const maze::World world = maze::load_world(file.string());
    if (!world.on_lattice()) {
      return fmt::format("{:<22} arena  {:g} x {:g} m", name, world.arena().width_m(), world.arena().height_m());
    }
    const maze::Maze &m = world.maze();
    return fmt::format("{:<22} maze   {} x {} cells", name, m.width(), m.height());
  } catch (const common::InputError &e) {
    return fmt::format("{:<22} ?      does not load: {}", name, e.what());
  }
}

}  // namespace

void add_worlds_command(CLI::App &cli, CommandContext &context) {
  auto *cmd = cli.add_subcommand("worlds", "list the shipped worlds, which every command finds by name from any folder");
  cmd->callback([&context] {
    const std::optional<std::filesystem::path> dir = shipped_worlds_dir();
    if (!dir) {
      throw common::InputError(fmt::format("no shipped worlds: no {} beside the program; set {} to the worlds' folder",
                                           kWorldsBesideProgram, kWorldsEnvironmentVariable));
    }
    std::cout << fmt::format("{:<22} {:<6} size\n", "world", "kind");
    for (const std::filesystem::path &file : shipped_world_files()) std::cout << shipped_world_line(file) << '\n';
    std::cout << fmt::format("in {} (a name, with or without its extension, is enough: maze_mapper run maze8x8)\n",
                             dir->string());
    context.status = 0;
  });
}

void add_show_command(CLI::App &cli, CommandContext &context) {
  auto *cmd = cli.add_subcommand("show", "print a world: a maze as a canonical micromouse text map, an arena drawn on a grid");
  struct Args {
    std::string world, boundary;
    std::optional<double> resolution_m;
  };
  auto args = std::make_shared<Args>();
  accept_shipped_world_names(
      cmd->add_option("WORLD", args->world,
                      "maze or arena file: text map, num, XML, .maz or room (detected by content), or a shipped world's name"))
      ->required();
  add_resolution_option(*cmd, args->resolution_m,
                        "the finest of 0.05, 0.1, 0.2, 0.25, 0.5, 1 ... m that draws an arena in at most 60 cells a side");
  add_boundary_option(*cmd, args->boundary);
  cmd->callback([args, &context] {
    const maze::World world = load_world_reporting(args->world, with_arena_overrides({}, args->boundary));
    if (!world.on_lattice()) {
      const maze::Arena &a = world.arena();
      std::cout << maze::draw_arena(a, args->resolution_m.value_or(maze::default_arena_resolution_m(a)));
    } else {
      if (args->resolution_m) common::print_stderr("warning: --resolution has no effect: {} is a grid maze\n", args->world);
      std::cout << maze::write_text_map(world.maze());
    }
    context.status = 0;
  });
}

void add_convert_command(CLI::App &cli, CommandContext &context) {
  auto *cmd = cli.add_subcommand("convert", "write a world in the format OUT's extension names");
  struct Args {
    std::string world, out, boundary;
    maze::WorldOverrides overrides;
    WebotsExport wbt;
    bool keep_origin = false;
  };
  auto args = std::make_shared<Args>();
  accept_shipped_world_names(
      cmd->add_option("WORLD", args->world,
                      "maze or arena file: text map, num, XML, .maz or room (detected by content), or a shipped world's name"))
      ->required();
  cmd->add_option("OUT", args->out,
                  "output file: .txt (text map), .num, .xml, .maz (16 x 16, binary), .wbt (Webots R2023b) or .room "
                  "(an arena; a maze's walls as rectangles)")
      ->required();
  add_cell_size_option(*cmd, args->overrides);
  add_boundary_option(*cmd, args->boundary);
  cmd->add_flag("--keep-origin", args->keep_origin,
               ".xml: keep the world's own origin (default centred on (0, 0), as the course's files are)");
  cmd->add_option("--robot", args->wbt.robot,
                  fmt::format(".wbt: the robot the world carries, one of {} (default {})", robot_names(), args->wbt.robot));
  cmd->add_option("--model", args->wbt.model,
                  ".wbt: the controller's mapping model (default cell with a lidar, else bump with bumpers, else depth)");
  cmd->add_option("--strategy", args->wbt.strategy,
                  fmt::format(".wbt: the controller's exploration strategy (default {})", args->wbt.strategy));
  cmd->add_option("--subcells", args->wbt.subcells,
                  fmt::format(".wbt: the controller's sub-cells per cell side, K (default {})", args->wbt.subcells));
  cmd->callback([cmd, args, &context] {
    const maze::Format format = maze::format_for_output(args->out);  // a bad extension fails before any reading
    common::refuse_output_over_input("", args->out, {args->world});
    // The controller's set-up travels in a .wbt only: for another format these do nothing.
    for (const char *option : {"--robot", "--model", "--strategy", "--subcells"}) {
      if (format != maze::Format::wbt && cmd->count(option) > 0) {
        common::print_stderr("warning: {} has no effect: only a .wbt world carries the robot and its controller\n",
                             option);
      }
    }
    if (format != maze::Format::xml && args->keep_origin) {
      common::print_stderr("warning: --keep-origin has no effect: only an .xml world is centred\n");
    }
    const maze::World world = load_world_reporting(args->world, with_arena_overrides(args->overrides, args->boundary));
    if (!world.on_lattice()) {
      maze::save_arena(world.arena(), args->out);  // .room or .xml; any other format is refused
      if (const auto dropped = maze::dropped_by(world.arena(), format)) {
        common::print_stderr("{}: warning: {}\n", args->out, *dropped);
      }
      if (args->keep_origin) common::print_stderr("warning: --keep-origin has no effect: an arena keeps its coordinates\n");
      context.status = 0;
      return;
    }
    const maze::Maze &maze = world.maze();
    if (format == maze::Format::wbt) {
      maze::write_file_atomically(
          args->out, webots_world(maze, std::filesystem::path(args->out).stem().string(), args->wbt));
    } else if (format == maze::Format::xml && args->keep_origin) {
      maze::write_file_atomically(args->out, maze::write_xml_keeping_origin(maze));
    } else {
      maze::save_world(maze, args->out);
    }
    // Said once the file is written: a write that fails is its error line alone.
    if (const auto dropped = maze::dropped_by(maze, format)) common::print_stderr("{}: warning: {}\n", args->out, *dropped);
    context.status = 0;
  });
}

namespace {

// "WxH" in metres ("3x3", "10x6.5"): two finite numbers; common::InputError otherwise (the
// generator checks their range).
std::array<double, 2> parse_arena_size(const std::string &text) {
  const std::size_t x = text.find_first_of("xX");
  const std::string_view whole(text);
  const bool split = x != std::string::npos;
  const std::optional<double> w = split ? common::parse_number<double>(whole.substr(0, x)) : std::nullopt;
  const std::optional<double> h = split ? common::parse_number<double>(whole.substr(x + 1)) : std::nullopt;
  common::require_input(w && h, fmt::format("an arena's size is WxH in metres, e.g. 3x3 (got '{}')", text));
  return {*w, *h};
}

// `generate arena`: rectangles placed at random on a floor (maze::generate_arena), as a room
// file on standard output or written as OUT's extension says (.room or .xml).
void add_generate_arena_command(CLI::App &generate, CommandContext &context) {
  auto *cmd = generate.add_subcommand("arena", "generate a random arena of rectangles and print it as a room file");
  struct Args {
    std::string size, sides, out;
    maze::ArenaGeneration generation;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("WxH", args->size,
                  fmt::format("the floor in metres, e.g. 3x3 (1 to {:g} each way), walled all round", maze::kMaxArenaSide_m))
      ->required();
  add_seed_option(*cmd, args->generation.seed, "the arena; the same seed gives the same arena");
  cmd->add_option("--obstacles", args->generation.obstacles,
                  fmt::format("how many rectangles (default {}; fewer when the start or the goal leaves no room)",
                              args->generation.obstacles));
  cmd->add_option("--sides", args->sides,
                  fmt::format("MIN,MAX: each rectangle's sides in metres, uniform between (default {:g},{:g})",
                              args->generation.min_side_m, args->generation.max_side_m));
  cmd->add_flag("--rotated", args->generation.rotated, "rectangles at random angles (default axis-aligned)");
  cmd->add_option("-o,--out", args->out, "FILE: write there (.room or .xml, the course's format) instead of standard output");
  cmd->callback([&generate, args, &context] {
    // A maze's option typed before `arena` would do nothing: refused before anything is written.
    for (const CLI::Option *option : generate.get_options()) {
      common::require_input(option->count() == 0 || option->get_name() == "--help",
                            fmt::format("{} is the maze's, given before `arena`; an arena's options follow `arena`",
                                        option->get_name()));
    }
    const std::array<double, 2> size = parse_arena_size(args->size);
    args->generation.width_m = size[0];
    args->generation.height_m = size[1];
    if (!args->sides.empty()) {
      const std::vector<double> sides = parse_number_list(args->sides, "--sides", 2);
      args->generation.min_side_m = sides[0];
      args->generation.max_side_m = sides[1];
    }
    const maze::Arena arena = maze::generate_arena(args->generation);
    if (args->out.empty()) {
      std::cout << maze::write_room(arena);
    } else {
      maze::save_arena(arena, args->out);  // .room or .xml; any other format is refused
    }
    context.status = 0;
  });
}

}  // namespace

void add_generate_command(CLI::App &cli, CommandContext &context) {
  auto *cmd =
      cli.add_subcommand("generate", "generate a random maze and print it as a text map (`generate arena`: an arena)");
  cmd->require_subcommand(0, 1);
  add_generate_arena_command(*cmd, context);
  struct Args {
    std::string size, algorithm = "dfs", out;
    std::uint64_t seed = common::kDefaultSeed;
    double loops = 0.0;
  };
  auto args = std::make_shared<Args>();
  // Required unless `generate arena` is the command (checked below: CLI11 would ask for it there too).
  cmd->add_option("WxH", args->size, "maze size in cells, e.g. 16x16 (1 to 4096 each way)");
  add_seed_option(*cmd, args->seed, "the maze; the same seed gives the same maze");
  cmd->add_option("--loops", args->loops,
                  fmt::format("fraction (0 to 1) of the perfect maze's interior walls removed (default {})", args->loops));
  cmd->add_option("--algorithm", args->algorithm, fmt::format("dfs, kruskal or prim (default {})", args->algorithm));
  cmd->add_option("-o,--out", args->out, "FILE: write there (format by extension) instead of standard output");
  add_old_spelling(*cmd, "--output", "-o/--out", [args](const std::string &file) { args->out = file; });
  cmd->callback([cmd, args, &context] {
    if (cmd->got_subcommand("arena")) return;
    common::require_input(!args->size.empty(),
                          "generate needs the maze's size WxH, e.g. 16x16 (or `generate arena WxH`)");
    const maze::Cell size = maze::parse_size(args->size);
    maze::GeneratorOptions options{size.x, size.y, args->seed, args->loops, maze::parse_algorithm(args->algorithm)};
    options.validate();
    if (!args->out.empty()) maze::format_for_output(args->out);
    const maze::Maze m = maze::generate_maze(options);
    if (args->out.empty()) {
      std::cout << maze::write_text_map(m);
    } else {
      maze::save_world(m, args->out);
      // As convert says it: a .num holds no goal, and the maze has one.
      if (const auto dropped = maze::dropped_by(m, maze::format_for_output(args->out))) {
        common::print_stderr("{}: warning: {}\n", args->out, *dropped);
      }
    }
    context.status = 0;
  });
}

}  // namespace app
