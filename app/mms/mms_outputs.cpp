#include "app/mms/mms_outputs.hpp"

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace app {
namespace {

using Json = nlohmann::ordered_json;

template <typename T>
Json or_null(const std::optional<T> &value) {
  return value ? Json(*value) : Json(nullptr);
}

// A stat as mms prints it (6 significant digits), as a JSON number: 47.4, not the float's
// 47.400001525878906.
Json stat(float value) { return std::stod(mms_number(value)); }

Json stat(const std::optional<float> &value) { return value ? stat(*value) : Json(nullptr); }

}  // namespace

std::string mms_summary_json(const RunOptions &options, const MmsOptions &mms, const MmsRun &run) {
  Json j = Json::parse(summary_json(options, run.summary));
  j.erase("strategy");  // the algorithm decides, not a strategy
  const MmsReport &r = run.mms;
  const MmsStats &s = r.stats;
  j["goal"] = run.summary.reached_goal ? "reached" : "not reached";
  j["algorithm"] = command_line(mms.command);
  j["walls"] = mms.walls == MmsWalls::truth ? "truth" : "sensed";
  j["mms_end"] = std::string(to_string(r.end));
  j["mms_end_message"] = r.message;
  j["lines"] = r.lines;
  j["crashes"] = r.crashes;
  j["total_distance"] = s.total_distance();
  j["total_turns"] = s.total_turns();
  j["total_effective_distance"] = stat(s.total_effective_distance());
  j["best_run_distance"] = or_null(s.best_run_distance());
  j["best_run_turns"] = or_null(s.best_run_turns());
  j["best_run_effective_distance"] = stat(s.best_run_effective_distance());
  j["score"] = stat(s.score());
  return j.dump(2) + "\n";
}

std::vector<NamedInput> program_inputs(const MmsOptions &mms) {
  std::vector<NamedInput> inputs;
  for (std::size_t i = 0; i < mms.command.size(); ++i) {
    inputs.push_back({i == 0 ? "the program" : "the program's argument", mms.command[i]});
  }
  return inputs;
}

const std::vector<std::string> &mms_own_names() {
  static const std::vector<std::string> names{"marks.txt"};
  return names;
}

std::vector<NamedFile> mms_own_files(const MmsRun &run) { return {{"marks.txt", render_marks(run.mms.marks, false)}}; }

}  // namespace app
