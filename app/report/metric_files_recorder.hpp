#pragma once
// The files of `room --out DIR` (a run in metres: app/run/metric_run.hpp), kept as the run
// goes: a MetricRunRecorder that prepares DIR (an OutputDir, the one writer of every kind's
// files) before the robot moves, records trace.csv, the snapshots' pictures and replay.html's
// frames during the run, and writes every file when it ends: the core files every run writes
// (map.pgm + map.yaml, map.png, truth.png, summary.json, trace.csv, snapshots/, replay.html)
// and the room's own, logodds.csv, thresholded.txt and wave.png.

#include <chrono>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "app/picture/map_picture.hpp"
#include "app/picture/metric_map_pictures.hpp"
#include "app/report/metric_replay_recorder.hpp"
#include "app/report/output_dir.hpp"
#include "app/run/metric_run.hpp"

namespace app {

// The files a room run adds to the run's: logodds.csv, thresholded.txt, wave.png (and the
// snapshots' NAME_wave.png).
const std::vector<std::string> &metric_own_names();
// logodds.csv: every cell's log-odds to 6 decimals, comma-separated, north row first.
std::string metric_logodds_csv(const sensing::MetricMap &map);
// map.pgm of the map: one pixel a cell, north up (pgm_pixel's tones).
std::string metric_pgm(const sensing::MetricMap &map);

class MetricFilesRecorder final : public MetricRunRecorder {
 public:
  // Prepares options.output.out_dir (which must be set), refused when an output would be the world
  // or --robot's file; the trace's header, the pictures' marks and tones, the first frame.
  void start(const MetricRunStart &start) override;
  // trace.csv's line and replay.html's frame when due.
  void on_step(const robot::MetricController &c) override;
  // NAME.png (and NAME_wave.png for wavefront), kept until the files are written.
  void on_snapshot(const robot::MetricController &c, const std::string &name) override;
  // Writes every file; a stop signal meanwhile ends the process with each file whole or absent.
  void finish(const MetricRunEnd &end) override;

 private:
  // The map's picture now as MAP.png (and the wave's, when there is one, as WAVE.png).
  std::vector<NamedFile> pictures_now(const robot::MetricController &c, const std::string &map,
                                      const std::string &wave) const;

  std::optional<OutputDir> dir_;
  sensing::ModelKind kind_ = sensing::ModelKind::ray;
  bool wavefront_ = false;
  double threshold_ = 0.0;
  std::string world_;
  double body_radius_m_ = 0.0;
  MapTones tones_;
  MetricPictureMarks marks_;
  std::string trace_;
  std::vector<NamedFile> snapshots_;  // snapshots/NAME.png and NAME_wave.png
  std::optional<MetricReplayRecorder> replay_;
};

// run_metric_world() with options.output.out_dir's files written by a MetricFilesRecorder when
// it is set, and the progress line on progress_fd when not -1.
MetricRunSummary run_metric_and_write(const maze::World &world, const RunOptions &options, std::ostream &out,
                               std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now(),
                               robot::StopPoll interrupted = nullptr, Report *report = nullptr,
                               int progress_fd = -1);

}  // namespace app
