#pragma once
// The directory of `run --out DIR`: made ready before the run, checked against the run's
// inputs, and after writing rid of what an earlier run left there (app/report/outputs.hpp writes
// the files).

#include <string>
#include <vector>

namespace app {

// Makes sure DIR can take the outputs before anything runs: creates it (and its parents)
// when missing, and checks that it is a directory a file can be created in (by creating and
// removing a probe file). Throws common::InputError "--out DIR: REASON" otherwise (a dangling
// symbolic link too: it is left as it is); then no directory it created is left behind, and
// nothing that was there is removed.
void prepare_output_dir(const std::string &dir);

// Throws common::InputError "--out DIR: REASON": the one form of every refusal of DIR.
[[noreturn]] void refuse_out_dir(const std::string &dir, const std::string &reason);

// A file a command reads, as the user named it: `what` says how ("the world", "--robot",
// "the program"), `path` is the path given.
struct NamedInput {
  std::string what;
  std::string path;
};

// The names run --out may write in its DIR; "snapshots/" stands for every snapshots/NAME.
const std::vector<std::string> &run_output_names();

// Throws common::InputError "--out DIR/NAME is also an input (WHAT PATH): refusing to
// overwrite it" when a file the command may write in DIR (`names`, relative to DIR; a name
// ending in "/" is every file of that folder) is one of `inputs` (device and inode, links
// followed), before anything runs. A character device (/dev/null) is no one's content.
void refuse_outputs_over_inputs(const std::string &dir, const std::vector<std::string> &names,
                                const std::vector<NamedInput> &inputs);

// Removes the files an earlier run left in DIR that this one did not write (`written`:
// names relative to DIR, "snapshots/01.png" for a snapshot): only files of the names
// write_outputs() writes (map.pgm ... plan.csv, snapshots/NN.png, snapshots/ when that
// empties it), and only regular files and links; nothing else in DIR is touched.
void remove_stale_outputs(const std::string &dir, const std::vector<std::string> &written);

}  // namespace app
