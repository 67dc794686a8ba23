#include "app/run/shipped_worlds.hpp"

#include <algorithm>
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

// The text map is what the num and XML copies of a world are made from: it wins a tie.
constexpr const char *kPreferredExtension = ".txt";

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

std::vector<std::filesystem::path> shipped_world_files() {
  std::vector<std::filesystem::path> files;
  const std::optional<std::filesystem::path> dir = shipped_worlds_dir();
  if (!dir) return files;
  std::error_code error;
  for (std::filesystem::directory_iterator it(*dir, error), end; !error && it != end; it.increment(error)) {
    if (it->is_regular_file(error) && it->path().stem() != "README") files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::optional<std::filesystem::path> shipped_world(const std::string &name) {
  if (name.empty() || name.find('/') != std::string::npos || name == "." || name == "..") return std::nullopt;
  std::vector<std::filesystem::path> stem_matches;
  for (const std::filesystem::path &file : shipped_world_files()) {
    if (file.filename() == name) return file;
    if (file.stem() == name) stem_matches.push_back(file);
  }
  if (stem_matches.size() == 1) return stem_matches.front();
  for (const std::filesystem::path &file : stem_matches) {
    if (file.extension() == kPreferredExtension) return file;
  }
  return std::nullopt;
}

std::string world_argument(const std::string &given) {
  std::error_code error;
  if (given.empty() || std::filesystem::exists(given, error)) return given;
  const std::filesystem::path path(given);
  if (const std::optional<std::filesystem::path> shipped = shipped_world(given)) return shipped->string();
  const std::optional<std::filesystem::path> by_last_part = shipped_world(path.filename().string());
  if (by_last_part && path.has_parent_path()) {
    throw common::InputError(fmt::format("cannot read {}: no such file; {} is a shipped world, found from any folder "
                                         "by its name: {}",
                                         given, by_last_part->filename().string(), path.stem().string()));
  }
  return given;
}

}  // namespace app
