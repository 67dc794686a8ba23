#pragma once
// Where the program finds the worlds it ships (worlds/ in the source tree, installed under
// share/maze_mapper/worlds): never through a path fixed when it was built, so that a copied,
// installed or packaged program finds them as well as one run from its build tree.

#include <filesystem>
#include <optional>
#include <string>

namespace app {

// The environment variable that names the shipped worlds' folder, overriding the rest.
inline constexpr const char *kWorldsEnvironmentVariable = "MAZE_MAPPER_WORLDS";
// The shipped worlds' folder relative to the folder the program is in (bin/ -> share/...).
// The build tree has the same layout: a link made at configure time to the source's worlds/.
inline constexpr const char *kWorldsBesideProgram = "../share/maze_mapper/worlds";
inline constexpr const char *kDefaultWorldName = "lab4x4.txt";

// The shipped worlds' folder: $MAZE_MAPPER_WORLDS when set and not empty (whether or not it
// exists: the user said so), else kWorldsBesideProgram from the running program's folder
// (/proc/self/exe) when that folder exists, else nothing.
std::optional<std::filesystem::path> shipped_worlds_dir();

// The world `run`, `plan`, `compare` and the program without arguments map when none is
// given: $MAZE_MAPPER_WORLDS/lab4x4.txt when the variable is set; else worlds/lab4x4.txt
// from the working directory when it exists there (a checkout's top, as the README runs);
// else lab4x4.txt in the folder beside the program. Throws common::InputError when none of
// these applies.
std::string default_world();

}  // namespace app
