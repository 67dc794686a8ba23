#pragma once
// `mms --out DIR`: what an algorithm's run adds to the files every run writes (report/'s
// FilesRecorder: map.pgm + map.yaml, map.png, truth.png, trace.csv, replay.html, snapshots):
// its summary.json and replay.html's table show the mms report (app/mms/mms_report.hpp), and
// marks.txt the algorithm's marks as the terminal shows them, without colour.

#include <string>
#include <vector>

#include "app/mms/mms_session.hpp"
#include "app/report/outputs.hpp"

namespace app {

// The files an mms run reads besides the world and --robot's file, for the output folder's
// check: the program and each of its arguments (any may name a file it reads: `python3
// DIR/algo.py`).
std::vector<NamedInput> program_inputs(const MmsOptions &mms);

// The files an mms run adds to the run's: marks.txt.
const std::vector<std::string> &mms_own_names();
std::vector<NamedFile> mms_own_files(const MmsRun &run);

}  // namespace app
