#pragma once
// The directory of `run --out DIR`: made ready before the run, checked against the run's
// inputs, and after writing rid of what an earlier run left there (app/report/outputs.hpp writes
// the files).

#include <string>
#include <vector>

namespace app {

// Makes sure DIR can take the outputs before anything runs: creates it (and its parents)
// when missing, and checks that it is a directory a file can be created in (by creating and
// removing a probe file). Throws common::InputError "--out DIR: REASON" otherwise; then no
// directory it created is left behind.
void prepare_output_dir(const std::string &dir);

// Throws common::InputError "--out DIR: REASON": the one form of every refusal of DIR.
[[noreturn]] void refuse_out_dir(const std::string &dir, const std::string &reason);

// Throws common::InputError "--out DIR/NAME is also an input ..." when one of the files the
// run may write in DIR is one of `inputs` (the world), before anything runs.
void refuse_outputs_over_inputs(const std::string &dir, const std::vector<std::string> &inputs);

// Removes the files an earlier run left in DIR that this one did not write (`written`:
// names relative to DIR, "snapshots/01.png" for a snapshot): only files of the names
// write_outputs() writes (map.pgm ... plan.csv, snapshots/NN.png, snapshots/ when that
// empties it), and only regular files and links; nothing else in DIR is touched.
void remove_stale_outputs(const std::string &dir, const std::vector<std::string> &written);

}  // namespace app
