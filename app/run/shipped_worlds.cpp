#include "app/run/shipped_worlds.hpp"

#include <cstdlib>
#include <system_error>

#include <fmt/format.h>

#include "common/error.hpp"

namespace app {
namespace {

// The folder of the running program, from /proc/self/exe (Linux); empty when unreadable.
std::filesystem::path program_dir() {
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path() : program.parent_path();
}

}  // namespace

std::optional<std::filesystem::path> shipped_worlds_dir() {
  const char *from_environment = std::getenv(kWorldsEnvironmentVariable);
  if (from_environment != nullptr && *from_environment != '\0') return std::filesystem::path(from_environment);
  const std::filesystem::path dir = program_dir();
  if (dir.empty()) return std::nullopt;
  const std::filesystem::path beside = (dir / kWorldsBesideProgram).lexically_normal();
  std::error_code error;
  if (!std::filesystem::is_directory(beside, error)) return std::nullopt;
  return beside;
}

std::string default_world() {
  const char *from_environment = std::getenv(kWorldsEnvironmentVariable);
  const bool environment_set = from_environment != nullptr && *from_environment != '\0';
  const std::filesystem::path in_working_dir = std::filesystem::path("worlds") / kDefaultWorldName;
  std::error_code error;
  if (!environment_set && std::filesystem::exists(in_working_dir, error)) return in_working_dir.string();
  if (const std::optional<std::filesystem::path> dir = shipped_worlds_dir()) return (*dir / kDefaultWorldName).string();
  throw common::InputError(fmt::format("no default world: {} is not in the working directory nor in {} beside the "
                                       "program; give a WORLD, or set {} to the worlds' folder",
                                       in_working_dir.string(), kWorldsBesideProgram, kWorldsEnvironmentVariable));
}

}  // namespace app
