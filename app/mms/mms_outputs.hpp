#pragma once
// `mms --out DIR`: what an algorithm's run adds to the files every run writes (report/'s
// FilesRecorder: map.pgm + map.yaml, map.png, truth.png, trace.csv, replay.html, snapshots):
// summary.json holding every key of the mms summary block (format_mms_summary) too, and
// marks.txt, the algorithm's marks as the terminal shows them, without colour.

#include <string>

#include "app/mms/mms_session.hpp"
#include "app/report/outputs.hpp"

namespace app {

// summary.json's text: the run's keys (summary_json) with the mms keys added: algorithm,
// walls, mms_end, mms_end_message, lines, crashes, and the stats (total_distance ... score,
// best-run values null until a run has finished).
std::string mms_summary_json(const RunOptions &options, const MmsOptions &mms, const MmsRun &run);

// Writes summary.json (replacing the recorder's) and marks.txt into dir, which the recorder
// prepared and filled.
void write_mms_outputs(const std::string &dir, const RunOptions &options, const MmsOptions &mms, const MmsRun &run);

}  // namespace app
