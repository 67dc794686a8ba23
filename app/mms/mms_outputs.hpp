#pragma once
// `mms --out DIR`: what an algorithm's run adds to the files every run writes (report/'s
// FilesRecorder: map.pgm + map.yaml, map.png, truth.png, trace.csv, replay.html, snapshots):
// summary.json holding every key of the mms summary block (format_mms_summary) too, and
// marks.txt, the algorithm's marks as the terminal shows them, without colour.

#include <string>
#include <vector>

#include "app/mms/mms_session.hpp"
#include "app/report/outputs.hpp"

namespace app {

// summary.json's text: the run's keys (summary_json) with the mms keys added: algorithm,
// walls, mms_end, mms_end_message, lines, crashes, and the stats (total_distance ... score,
// best-run values null until a run has finished).
std::string mms_summary_json(const RunOptions &options, const MmsOptions &mms, const MmsRun &run);

// The names write_mms_outputs may write in its dir (run --out's and marks.txt).
std::vector<std::string> mms_output_names();

// The files an mms run reads, for refuse_outputs_over_inputs: the world, --robot's file, the
// program and each of its arguments (any may name a file it reads: `python3 DIR/algo.py`).
std::vector<NamedInput> mms_inputs(const RunOptions &options, const MmsOptions &mms);

// Writes summary.json (replacing the recorder's) and marks.txt into dir, which the recorder
// prepared and filled.
void write_mms_outputs(const std::string &dir, const RunOptions &options, const MmsOptions &mms, const MmsRun &run);

}  // namespace app
