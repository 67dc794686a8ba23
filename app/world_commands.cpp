// The world subcommands: show, convert, generate.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "app/run_cli.hpp"
#include "commands.hpp"
#include "app/webots_export.hpp"
#include "maze/generator.hpp"
#include "maze/text_map.hpp"
#include "maze/world.hpp"

namespace app {

maze::World load_world_reporting(const std::string &path, const maze::WorldOverrides &overrides) {
  maze::World world = maze::load_world(path, overrides);
  for (const std::string &warning : world.warnings) fmt::print(stderr, "{}\n", warning);
  return world;
}

void add_show_command(CLI::App &cli, CommandContext &context) {
  auto *cmd = cli.add_subcommand("show", "Print a world as a canonical micromouse text map");
  auto world = std::make_shared<std::string>();
  cmd->add_option("WORLD", *world, "maze file: text map, num or XML (detected by content)")->required();
  cmd->callback([world, &context] {
    std::cout << maze::write_text_map(load_world_reporting(*world).maze);
    context.status = 0;
  });
}

void add_convert_command(CLI::App &cli, CommandContext &context) {
  auto *cmd = cli.add_subcommand("convert", "Write a world in the format OUT's extension names");
  struct Args {
    std::string world, out;
    WorldInput world_input;
    WebotsExport wbt;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("WORLD", args->world, "maze file: text map, num or XML (detected by content)")->required();
  cmd->add_option("OUT", args->out, "output file: .txt (text map), .num, .xml or .wbt (Webots R2023b)")->required();
  add_cell_size_option(*cmd, args->world_input);
  cmd->add_option("--robot", args->wbt.robot, ".wbt: the robot the world carries (maze_mapper robot lists them)")
      ->capture_default_str();
  cmd->add_option("--model", args->wbt.model, ".wbt: the controller's mapping model (default: cell with a lidar, "
                                          "else bump with bumpers, else depth)");
  cmd->add_option("--strategy", args->wbt.strategy, ".wbt: the controller's exploration strategy")->capture_default_str();
  cmd->add_option("--subcells", args->wbt.subcells, ".wbt: the controller's sub-cells per cell side (K)")
      ->capture_default_str();
  cmd->callback([args, &context] {
    const maze::Format format = maze::format_for_output(args->out);  // a bad extension fails before any reading
    const maze::WorldOverrides overrides = to_world_overrides(args->world_input);
    const maze::Maze maze = load_world_reporting(args->world, overrides).maze;
    if (const auto dropped = maze::dropped_by(maze, format)) fmt::print(stderr, "{}: warning: {}\n", args->out, *dropped);
    if (format == maze::Format::wbt) {
      maze::write_file_atomically(
          args->out, webots_world(maze, std::filesystem::path(args->out).stem().string(), args->wbt));
    } else {
      maze::save_world(maze, args->out);
    }
    context.status = 0;
  });
}

void add_generate_command(CLI::App &cli, CommandContext &context) {
  auto *cmd = cli.add_subcommand("generate", "Generate a random maze and print it as a text map");
  struct Args {
    std::string size, algorithm = "dfs", out;
    std::uint64_t seed = common::kDefaultSeed;
    double loops = 0.0;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("WxH", args->size, "maze size in cells, e.g. 16x16 (1 to 4096 each way)")->required();
  cmd->add_option("--seed", args->seed, "random seed; the same seed gives the same maze")->capture_default_str();
  cmd->add_option("--loops", args->loops, "fraction (0 to 1) of the perfect maze's interior walls removed")
      ->capture_default_str();
  cmd->add_option("--algorithm", args->algorithm, "dfs, kruskal or prim")->capture_default_str();
  cmd->add_option("-o,--output", args->out, "write to FILE (format by extension) instead of standard output");
  cmd->callback([args, &context] {
    const maze::Cell size = maze::parse_size(args->size);
    maze::GeneratorOptions options{size.x, size.y, args->seed, args->loops, maze::parse_algorithm(args->algorithm)};
    options.validate();
    if (!args->out.empty()) maze::format_for_output(args->out);
    const maze::Maze m = maze::generate_maze(options);
    if (args->out.empty()) {
      std::cout << maze::write_text_map(m);
    } else {
      maze::save_world(m, args->out);
    }
    context.status = 0;
  });
}

}  // namespace app
