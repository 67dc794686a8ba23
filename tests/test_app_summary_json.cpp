// summary.json holds every key the printed summary block prints, and every option in effect:
// checked on runs that print the optional keys (--plan-to, --speed-run, floodfill's goal and
// shortest path, --threshold), so that a key added to the block and not to the file fails here.

#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/report/files_recorder.hpp"
#include "app/cli/commands.hpp"
#include "app/run/run.hpp"

namespace {

namespace fs = std::filesystem;

// The keys of the summary block: the `key: value` lines from "world: " on.
std::vector<std::string> printed_keys(const std::string &output) {
  std::vector<std::string> keys;
  std::istringstream in(output.substr(output.rfind("\nworld: ") + 1));
  for (std::string line; std::getline(in, line);) {
    const std::size_t colon = line.find(": ");
    REQUIRE(colon != std::string::npos);
    keys.push_back(line.substr(0, colon));
  }
  return keys;
}

struct Run {
  std::vector<std::string> keys;
  nlohmann::json json;
};

// `maze_mapper run ARGS... --out DIR --quiet` on lab4x4: the printed keys and summary.json.
Run run_with_out(std::vector<std::string> args) {
  const fs::path dir = fs::temp_directory_path() / ("maze_mapper_summary_json_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  args.insert(args.begin(), {"maze_mapper", "run", std::string(WORLDS_DIR) + "/lab4x4.txt", "--quiet", "--out",
                             dir.string()});
  std::vector<const char *> argv;
  for (const std::string &a : args) argv.push_back(a.c_str());
  const app::RunOptions options = app::parse_run_options(static_cast<int>(argv.size()), argv.data());
  std::ostringstream out;
  app::run_and_write(options, out);
  std::ifstream file(dir / "summary.json");
  Run run{printed_keys(out.str()), nlohmann::json::parse(file)};
  fs::remove_all(dir);
  return run;
}

}  // namespace

TEST_CASE("summary.json: every key of the printed summary, on runs that print the optional ones") {
  const std::vector<std::vector<std::string>> runs{
      {"--plan-to", "3,3", "--dilate", "1"},
      {"--strategy", "floodfill", "--speed-run"},
      {"--strategy", "floodfill", "--threshold", "0.2", "--plan-to", "0,0"},
      {"--model", "bump", "--log-base", "10", "--threshold", "-0.5", "--max-steps", "2000"},
      {"--localize", "--motion", "0.9"},
  };
  std::vector<std::string> seen;
  for (const std::vector<std::string> &args : runs) {
    CAPTURE(args.front());
    const Run run = run_with_out(args);
    CHECK(run.keys.size() >= 17);
    for (const std::string &key : run.keys) {
      CAPTURE(key);
      CHECK(run.json.contains(key));
      if (run.json.contains(key)) CHECK_FALSE(run.json.at(key).is_null());
      seen.push_back(key);
    }
  }
  // The runs above did print the optional keys.
  for (const char *key : {"threshold", "goal", "shortest_path", "plan", "plan_length", "search", "speed_run",
                          "speed_run_turns", "localization"}) {
    CAPTURE(key);
    CHECK(std::find(seen.begin(), seen.end(), key) != seen.end());
  }
}

TEST_CASE("summary.json: every option in effect, one object a concern") {
  const Run run = run_with_out({"--seed", "7", "--dropout", "0.01", "--spikes", "0.02", "--wheel-slip", "0.03",
                                "--clamp", "-2", "3.5", "--p-free", "0.35", "--start", "0,0,E", "--max-steps", "3000"});
  const nlohmann::json &o = run.json.at("options");
  CHECK(o.at("simulation").at("seed") == 7);
  CHECK(o.at("simulation").at("dropout") == 0.01);
  CHECK(o.at("simulation").at("spikes") == 0.02);
  CHECK(o.at("simulation").at("wheel_slip") == 0.03);
  CHECK(o.at("simulation").at("stuck_bumper").is_null());
  CHECK(o.at("simulation").at("noise").is_null());
  CHECK(o.at("sensor").at("p_free") == 0.35);
  CHECK(o.at("sensor").at("clamp") == nlohmann::json::array({-2.0, 3.5}));
  CHECK(o.at("sensor").at("log_base") == "e");
  CHECK(o.at("model").at("kind") == "cell");
  CHECK(o.at("model").at("hit_depth") == 0);
  CHECK(o.at("range_model").contains("pie_half_angle_rad"));
  CHECK(o.at("strategy") == "dfs");
  CHECK(o.at("robot") == "hambot");
  CHECK(o.at("max_steps") == 3000);
  CHECK(o.at("threshold").is_null());
  CHECK(o.at("world_overrides").at("start") == nlohmann::json::array({0, 0, "east"}));
  CHECK(o.at("plan").at("dilate") == 0);
  CHECK(o.at("output").at("quiet") == true);
  CHECK(o.at("output").at("trace_steps") == false);
  CHECK(o.at("output").at("picture_formats") == nlohmann::json::array({"png"}));
  CHECK(o.at("world_overrides").at("centre_goals") == false);
  CHECK(run.json.at("seed") == 7);
  // Without --max-steps, the limit in effect: 1000 a cell, at least 100000.
  CHECK(run_with_out({}).json.at("options").at("max_steps") == 100000);
}

TEST_CASE("summary.json: the probabilities a run marked with, the set-up's own where it has them") {
  const Run pie = run_with_out({"--model", "pie"});
  CHECK(pie.json["options"]["sensor"]["p_free"] == 0.4);
  CHECK(pie.json["options"]["sensor"]["p_occ"] == 0.7);
  CHECK(pie.json["options"]["sensor"]["probabilities"] == "the model's own (course numbers)");
  const Run depth = run_with_out({"--model", "depth", "--log-base", "10"});
  CHECK(depth.json["options"]["sensor"]["p_robot"] == 0.3);
  CHECK(depth.json["options"]["sensor"]["p_occ"] == 0.99999);
  const Run cone = run_with_out({"--model", "cone", "--p-free", "0.2", "--p-occ", "0.8"});
  CHECK(cone.json["options"]["sensor"]["p_free"] == 0.2);
  CHECK(cone.json["options"]["sensor"]["probabilities"] == "--p-free, --p-occ");
  CHECK_FALSE(cone.json["options"]["sensor"].contains("p_robot"));
}
