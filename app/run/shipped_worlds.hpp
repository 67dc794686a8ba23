#pragma once
// Where the program finds the worlds it ships (worlds/ in the source tree, installed under
// share/maze_mapper/worlds): never through a path fixed when it was built, so that a copied,
// installed or packaged program finds them as well as one run from its build tree.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

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

// The shipped worlds: the regular files of shipped_worlds_dir() but its README, sorted by
// name; empty when there is no such folder.
std::vector<std::filesystem::path> shipped_world_files();

// The shipped world `name` names: the file of that name, else the one file whose name without
// its extension is `name` (maze8x8 -> maze8x8.txt; lab4x4 names lab4x4.txt, .num and .xml
// and so lab4x4.txt, the text map, which the others are made from). Nothing for a name with a
// folder in it, or one no shipped world has.
std::optional<std::filesystem::path> shipped_world(const std::string &name);

// A WORLD as the command line gives it: the path itself when something is there, else the
// shipped world its name names (`maze_mapper run maze8x8` from any folder). A path with a
// folder that is not there but whose last part names a shipped world throws
// common::InputError saying so (`worlds/maze8x8.txt` typed outside a checkout); any other
// path is returned as it is, for the reader's own "cannot read" error.
std::string world_argument(const std::string &given);

}  // namespace app
