#pragma once
// The directory of `--out DIR`: made ready before the run, checked against the run's inputs,
// and after writing rid of what an earlier run left there. OutputDir is the one writer of a
// run's files, whatever its kind (app/report/outputs.hpp makes a maze run's files).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/interrupt.hpp"
#include "common/output_deadline.hpp"

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

// "wrote DIR/: map.pgm, map.yaml, ..., snapshots/ (3 files, 01.png to 03.png), ...": the
// names in `written` (relative to dir), the snapshot_files from first_snapshot on as one.
std::string wrote_line(const std::string &dir, const std::vector<std::string> &written, std::size_t first_snapshot,
                       std::size_t snapshot_files);

// A file of a run's DIR: its name there ("summary.json", "snapshots/t15s.png") and its bytes.
struct NamedFile {
  std::string name;
  std::string bytes;
};

// The names a command that is no run writes in its --out DIR, declared whole (map-log's): its
// OutputDir writes, checks and removes none of a run's names, so a run's directory keeps its
// files when such a command writes there.
struct OwnNamesOnly {
  std::vector<std::string> names;
};

// The --out DIR of one run of any kind (a maze run, a room run, an mms program's run): the one
// writer of its files, the core ones (run_output_names: summary.json, trace.csv, map.pgm +
// map.yaml, map.png, truth.png, replay.html, snapshots/...) and what the kind adds
// (marks.txt, logodds.csv, ...); and of the files of a command that is no run (OwnNamesOnly).
//   - Made ready once, before the run: prepare_output_dir, then refused (common::InputError)
//     when a file it may write (the core names and `own_names`) is one of `inputs`.
//   - Each file is written atomically under a name so declared (another name is a
//     std::logic_error: what is written is what was checked against the inputs); a name in a
//     folder ("snapshots/01.png") creates the folder. A full disk throws common::NoSpaceError.
//   - From the first file written until finish(), a stop signal ends the process, each file
//     whole or absent (common::SignalsEndProcess), even while the run's SignalsStopWork lives.
//     When a stop signal ended the run, its files get common::kStoppedOutputBudget_ms from
//     the first one on (common/output_deadline.hpp): a writer writes summary.json and
//     trace.csv first.
//   - finish() removes what an earlier run left that this one did not write, among the names
//     declared (a regular file or a link, nothing else; snapshots/NN.png, and snapshots/ when
//     that empties it), and names the files written on stderr, one wrote_line() (in the
//     order a reader looks for them: the core names as run_output_names() has them, the
//     snapshots after trace.csv, then the kind's own names as written).
class OutputDir {
 public:
  OutputDir(std::string dir, const std::vector<NamedInput> &inputs, const std::vector<std::string> &own_names = {});
  OutputDir(std::string dir, const std::vector<NamedInput> &inputs, OwnNamesOnly names);
  OutputDir(const OutputDir &) = delete;
  OutputDir &operator=(const OutputDir &) = delete;

  const std::string &path() const { return dir_; }
  // DIR/name, written atomically.
  void write(const std::string &name, std::string_view bytes);
  // A file written during the run (trace.csv as the steps come): its temporary renamed into place.
  void commit(const std::string &name, common::OutputFile &file);
  void finish();

 private:
  // Checks that `name` was declared, creates its folder, and from the first file on lets a
  // stop signal end the process (and, after one, starts the budget).
  void begin(const std::string &name);
  void written(const std::string &name);

  std::string dir_;
  std::vector<std::string> names_;  // what it may write; "snapshots/" every file of that folder
  std::vector<std::string> written_;
  std::optional<common::SignalsEndProcess> writing_;
  std::optional<common::StoppedOutputDeadline> deadline_;  // a run a stop signal ended
};

}  // namespace app
