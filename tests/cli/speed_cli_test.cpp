// --speed and --climb-speed end to end (docs/model.md, "Speed and time"): the same mission,
// step for step, reported in seconds of the step; the trace and the exports follow.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/cli_runner.hpp"

namespace hullinspect::testing {
namespace {

nlohmann::json run_json(std::vector<std::string> extra) {
  std::vector<std::string> args = {"run", "-a", "lawnmower", "-n", "4", "--json"};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = run_cli(args);
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(SpeedCli, SameStepsReportedInSecondsOfTheStep) {
  const auto paper = run_json({});
  ASSERT_TRUE(paper["T_m"].is_number_integer());  // the paper's output keeps its integers
  EXPECT_FALSE(paper.contains("step_seconds"));
  // 0.5 m cells at 1 m/s: steps of 0.5 s; climbing at 1 m/s keeps u_z = 1 step, so the mission
  // is the same step for step and every time halves.
  const auto fast = run_json({"--speed", "1", "--climb-speed", "1"});
  EXPECT_EQ(fast["steps"], paper["steps"]);
  EXPECT_EQ(fast["moves"], paper["moves"]);
  EXPECT_DOUBLE_EQ(fast["T_c"].get<double>(), paper["T_c"].get<double>() * 0.5);
  EXPECT_DOUBLE_EQ(fast["T_m"].get<double>(), paper["T_m"].get<double>() * 0.5);
  EXPECT_EQ(fast["step_seconds"], 0.5);
  EXPECT_EQ(fast["plane_change_steps"], 1);
  // The default climb speed stays 0.5 m/s: at 1 m/s a plane change now takes 2 steps of 0.5 s.
  const auto slow_climb = run_json({"--speed", "1"});
  EXPECT_EQ(slow_climb["plane_change_steps"], 2);
  EXPECT_GT(slow_climb["steps"].get<int>(), paper["steps"].get<int>());
}

TEST(SpeedCli, TraceAndCsvExportCarryTheStep) {
  const auto dir = make_temp_dir("speed-export");
  const auto r =
      run_cli({"run", "-a", "lawnmower", "-n", "2", "--speed", "2", "--climb-speed", "2", "--trace",
               dir + "/trace.json", "--export", dir + "/plans", "--format", "csv"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto trace = nlohmann::json::parse(read(dir + "/trace.json"));
  EXPECT_EQ(trace["step_seconds"], 0.25);
  EXPECT_EQ(trace["parameters"]["speed"], 2.0);
  // The csv's last row is at the last frame's time: frames × 0.25 s.
  const std::string csv = read(dir + "/plans/uav0.csv");
  const auto last_line = csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
  const auto t_field = last_line.substr(last_line.find(',') + 1);
  const double t = std::stod(t_field.substr(0, t_field.find(',')));
  const auto last_t = trace["frames"].back()["t"].get<int>();
  EXPECT_LE(t, last_t * 0.25 + 1e-9);
  EXPECT_GT(t, 0.0);
  EXPECT_DOUBLE_EQ(t * 4, std::round(t * 4));  // a whole number of 0.25 s steps
  std::filesystem::remove_all(dir);
}

// runs.csv of an experiment with a speed: T_c, T_m and the bounds in seconds of the step, read
// back by `report` (whose row check converts them to steps); the run ids of the paper's configs
// are not those of the same config with a speed.
TEST(SpeedCli, ExperimentTimesAreSecondsOfTheStep) {
  const auto dir = make_temp_dir("speed-experiment");
  std::ofstream(dir + "/hull.txt") << "XXXXXXXXXXXX\nXXXXXXXXXXXX\nXXXXXXXXXXXX\nXXXXXXXXXXXX\n";
  const std::string config =
      "hull: hull.txt\nuavs: 2\nalgorithms: [lawnmower]\ninstances: 2\n"
      "time_limit: 2000\ncurve: {step: 10, end: 100}\n";
  std::ofstream(dir + "/paper.yaml") << "name: paper\n" << config;
  std::ofstream(dir + "/fast.yaml") << "name: fast\n" << config << "speed: 2\nclimb-speed: 2\n";
  for (const char* name : {"paper", "fast"}) {
    const auto r = run_cli({"experiment", "--config", dir + "/" + name + ".yaml", "--out",
                            dir + "/" + name, "--jobs", "1"});
    ASSERT_EQ(r.status, 0) << r.err;
  }
  const auto rows = [&](const std::string& name) {
    std::vector<std::vector<std::string>> out;
    std::istringstream in(read(dir + "/" + name + "/runs.csv"));
    std::string line;
    while (std::getline(in, line)) {
      std::vector<std::string> fields;
      std::istringstream f(line);
      std::string field;
      while (std::getline(f, field, ',')) fields.push_back(field);
      out.push_back(fields);
    }
    return out;
  };
  const auto paper = rows("paper");
  const auto fast = rows("fast");
  ASSERT_EQ(paper.size(), 3u);
  ASSERT_EQ(fast.size(), 3u);
  const auto column = [&](const std::string& name) {
    const auto& h = paper[0];
    return static_cast<std::size_t>(std::find(h.begin(), h.end(), name) - h.begin());
  };
  for (std::size_t i = 1; i < 3; ++i) {
    EXPECT_NE(fast[i][0], paper[i][0]);  // another experiment, other run ids
    EXPECT_EQ(fast[i][column("steps")], paper[i][column("steps")]);
    for (const char* time : {"T_c", "T_m", "bound_T_c", "bound_T_m"}) {
      EXPECT_DOUBLE_EQ(std::stod(fast[i][column(time)]), std::stod(paper[i][column(time)]) / 4)
          << time;
    }
  }
  const auto report = run_cli({"report", dir + "/fast", "--out", dir + "/report", "--no-figures"});
  EXPECT_EQ(report.status, 0) << report.err;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hullinspect::testing
