#pragma once
// The part of `--out DIR` a run in metres (`room`: app/run/metric/run.hpp) keeps as it goes,
// for the FilesRecorder (app/report/files_recorder.hpp), which writes every kind's files:
// trace.csv's rows, the snapshots' pictures and replay.html's frames (app/report/map_frames.hpp)
// during the run; at its end the core files (map.pgm + map.yaml, map.png, truth.png,
// summary.json, trace.csv, snapshots/, replay.html) and the room's own, logodds.csv,
// thresholded.txt and wave.png.

#include <string>
#include <vector>

#include "app/picture/map_picture.hpp"
#include "app/picture/metric/map_pictures.hpp"
#include "app/report/map_frames.hpp"
#include "app/report/output_dir.hpp"
#include "app/run/run_observer.hpp"

namespace app {

// The files a room run adds to the run's: logodds.csv, thresholded.txt, wave.png (and the
// snapshots' NAME_wave.png).
const std::vector<std::string> &metres_own_names();

class MetresRecord {
 public:
  // The trace's header, the pictures' marks and tones, the replay's first frame.
  MetresRecord(const RunOptions &options, const MetresRunStart &start);
  // trace.csv's line, replay.html's frame when due, the snapshots due.
  void on_step(const RunStep &step);
  // Writes every file into `out` (which the caller finishes).
  void write(OutputDir &out, const MetresRunEnd &end);

 private:
  // The map's picture now as MAP.png (and the wave's, when there is one, as WAVE.png).
  std::vector<NamedFile> pictures_now(const robot::MetricController &c, const std::string &map,
                                      const std::string &wave) const;

  sensing::ModelKind kind_ = sensing::ModelKind::ray;
  bool wavefront_ = false;
  double threshold_ = 0.0;
  std::string world_;
  double body_radius_m_ = 0.0;
  MapTones tones_;
  MetricPictureMarks marks_;
  std::string trace_;
  std::vector<NamedFile> snapshots_;  // snapshots/NAME.png and NAME_wave.png
  MapFrames replay_{PathPoses::at_frames};
};

}  // namespace app
