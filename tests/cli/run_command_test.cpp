// `hullinspect run` end to end through the built binary.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include "support/cli_runner.hpp"

namespace hullinspect::testing {
namespace {

struct BadInput {
  std::vector<std::string> args;
  std::string message;  // the whole stderr line
};

class RunBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(RunBadInput, OneLineExitTwoNoOutputFile) {
  const auto dir = make_temp_dir("bad-input");
  const std::string trace = dir + "/trace.json";
  const std::string html = dir + "/mission.html";
  std::vector<std::string> args = {"run", "--trace", trace, "--html", html};
  args.insert(args.end(), GetParam().args.begin(), GetParam().args.end());
  const auto r = run_cli(args);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, GetParam().message + "\n");
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(std::filesystem::exists(trace));
  EXPECT_FALSE(std::filesystem::exists(html));
  EXPECT_TRUE(std::filesystem::is_empty(dir));  // not even a temporary file
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(
    Table, RunBadInput,
    ::testing::Values(
        BadInput{{"--uavs", "0"}, "hullinspect: --uavs: must be at least 1 (got 0)"},
        BadInput{{"--uavs", "-3"}, "hullinspect: --uavs: must be at least 1 (got -3)"},
        BadInput{{"--uavs", "7000"},
                 "hullinspect: --uavs: must be at most the 6361 hull cells (got 7000)"},
        BadInput{{"--s1", "4"}, "hullinspect: --s1: must be a positive odd integer (got 4)"},
        BadInput{{"--s2", "8"},
                 "hullinspect: --s2: must be an odd integer greater than s1 = 5 (got 8)"},
        BadInput{{"--s1", "7", "--s2", "7"},
                 "hullinspect: --s2: must be an odd integer greater than s1 = 7 (got 7)"},
        BadInput{{"--s2", "3"},
                 "hullinspect: --s2: must be an odd integer greater than s1 = 5 (got 3)"},
        BadInput{{"--p-c", "1.5"}, "hullinspect: --p-c: must be a number in [0, 1] (got '1.5')"},
        BadInput{{"--p-tp", "-0.1"},
                 "hullinspect: --p-tp: must be a number in [0, 1] (got '-0.1')"},
        BadInput{{"--p-fp", "2"}, "hullinspect: --p-fp: must be a number in [0, 1] (got '2')"},
        BadInput{{"--l-c", "4"}, "hullinspect: --l-c: must be a positive odd integer (got 4)"},
        BadInput{{"--theta", "0"},
                 "hullinspect: --theta: must be in (0, 180) degrees, exclusive (got 0)"},
        BadInput{{"--theta", "180"},
                 "hullinspect: --theta: must be in (0, 180) degrees, exclusive (got 180)"},
        BadInput{{"--theta", "-5"},
                 "hullinspect: --theta: must be in (0, 180) degrees, exclusive (got -5)"},
        BadInput{{"--time-limit", "0"},
                 "hullinspect: --time-limit: must be at least 1 step (got 0)"},
        BadInput{{"--hull", "/nonexistent/hull.txt"},
                 "hullinspect: /nonexistent/hull.txt: cannot open the hull file"},
        BadInput{{"--scenario", "stormy"},
                 "hullinspect: --scenario: unknown scenario 'stormy' (known: perfect, imperfect, "
                 "inhomogeneous, combined)"},
        BadInput{{"--algorithm", "lawnmower", "--alpha", "0.3"},
                 "hullinspect: --alpha: unknown option (known: partitioner, partition-seed, "
                 "partitioner.<key>, prior-weights, prior-statistics)"},
        BadInput{{"--seed", "x1"},
                 "hullinspect: --seed: must be an integer in [0, 18446744073709551615] (got 'x1') "
                 "(see --help)"},
        BadInput{{"--start", "3;4"}, "hullinspect: --start: expects X,Y (got '3;4')"},
        BadInput{
            {"--uavs", "abc"},
            "hullinspect: --uavs: must be an integer in [1, 16777216] (got 'abc') (see --help)"}));

TEST(RunCommand, SummaryCountsOneUavInTheSingular) {
  const auto one = run_cli({"run", "--uavs", "1", "--seed", "2"});
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_TRUE(one.out.starts_with("lawnmower with 1 UAV, s1 = 5, s2 = 7, seed 2: complete\n"))
      << one.out;
  const auto two = run_cli({"run", "--uavs", "2", "--seed", "2"});
  ASSERT_EQ(two.status, 0) << two.err;
  EXPECT_TRUE(two.out.starts_with("lawnmower with 2 UAVs, s1 = 5, s2 = 7, seed 2: complete\n"))
      << two.out;
}

TEST(RunCommand, UnknownAlgorithmListsTheKnownOnes) {
  const auto r = run_cli({"run", "--algorithm", "zigzag"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("hullinspect: --algorithm: unknown algorithm 'zigzag' (known: ", 0), 0u)
      << r.err;
  EXPECT_NE(r.err.find("lawnmower"), std::string::npos);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
}

TEST(RunCommand, MalformedHullFileNamesFileAndLine) {
  const auto dir = make_temp_dir("bad-hull");
  const std::string hull = dir + "/hull.txt";
  std::ofstream(hull) << "XXX\nX?X\n";
  const auto r = run_cli({"run", "--hull", hull});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "hullinspect: " + hull +
                ":2: unexpected character '?' in column 2; a text mask uses 'X' or '#' (hull) "
                "and '.' (not hull)\n");
  std::filesystem::remove_all(dir);
}

TEST(RunCommand, JsonHasEveryDocumentedField) {
  const auto r = run_cli({"run", "--json", "--uavs", "4", "--s2", "9", "--seed", "5"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"algorithm", "uavs", "s1", "s2", "seed", "complete", "T_c", "T_m", "moves", "plane_changes",
        "hovers", "redundant_observations", "planner_seconds"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["uavs"], 4);
  EXPECT_EQ(j["s2"], 9);
  EXPECT_EQ(j["seed"], 5);
  EXPECT_EQ(j["complete"], true);
  EXPECT_LE(j["T_c"].get<int>(), j["T_m"].get<int>());
}

TEST(RunCommand, JsonWithLaunchSitesHasTheBoundAndTheRatios) {
  const auto r = run_cli(
      {"run", "--json", "--uavs", "4", "--seed", "5", "--launch", "115,0", "--endurance", "400"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("bound_T_c"));
  ASSERT_TRUE(j.contains("bound_T_m"));
  const double t_c = j["T_c"].get<double>(), t_m = j["T_m"].get<double>();
  const double b_c = j["bound_T_c"].get<double>(), b_m = j["bound_T_m"].get<double>();
  EXPECT_GT(b_c, 0);
  EXPECT_LE(b_c, t_c);
  EXPECT_LE(b_m, t_m);
  EXPECT_NEAR(j["T_c_ratio"].get<double>(), t_c / b_c, 5e-4);
  EXPECT_NEAR(j["T_m_ratio"].get<double>(), t_m / b_m, 5e-4);
  // Without launch sites the keys stay as they were.
  const auto plain = nlohmann::json::parse(run_cli({"run", "--json", "--seed", "5"}).out);
  EXPECT_FALSE(plain.contains("bound_T_m"));
}

TEST(RunCommand, TimeLimitReportsIncompleteWithoutNumbers) {
  const auto r = run_cli({"run", "--json", "--time-limit", "50"});
  EXPECT_EQ(r.status, 3);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["complete"], false);
  EXPECT_TRUE(j["T_m"].is_null());
  EXPECT_EQ(j["steps"], 50);
}

TEST(RunCommand, TraceIsWrittenAndCompactForEightUavs) {
  const auto dir = make_temp_dir("trace");
  const std::string trace = dir + "/t.json";
  const auto r = run_cli({"run", "--uavs", "8", "--trace", trace, "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(trace);
  const auto t = nlohmann::json::parse(in);
  EXPECT_EQ(t["format"], "hullinspect-trace");
  EXPECT_EQ(t["frames"].size(), t["result"]["steps"].get<std::size_t>() + 1);
  EXPECT_EQ(t["frames"][0]["u"].size(), 8u * 5);
  EXPECT_EQ(t["truth"].size(), 30u);
  EXPECT_EQ(t["partition"].size(), 30u);
  // Replaying the changes from the initial map ends on a fully inspected map.
  std::vector<std::string> map = t["initial_map"].get<std::vector<std::string>>();
  for (const auto& f : t["frames"]) {
    const auto& c = f["c"];
    for (std::size_t i = 0; i + 1 < c.size(); i += 2) {
      const int cell = c[i].get<int>();
      map[static_cast<std::size_t>(cell / 230)][static_cast<std::size_t>(cell % 230)] =
          static_cast<char>('0' + c[i + 1].get<int>());
    }
  }
  for (const auto& row : map) {
    for (char ch : row) EXPECT_TRUE(ch == '.' || ch == '1' || ch == '3') << ch;
  }
  EXPECT_LT(std::filesystem::file_size(trace), 2u * 1024 * 1024);
  std::filesystem::remove_all(dir);
}

TEST(RunCommand, HelpDocumentsEveryOption) {
  const auto r = run_cli({"run", "--help"});
  EXPECT_EQ(r.status, 0);
  for (const char* opt :
       {"--algorithm", "--uavs", "--s1",   "--s2",   "--theta",       "--seed",       "--p-c",
        "--l-c",       "--p-tp", "--p-fp", "--hull", "--partitioner", "--time-limit", "--json",
        "--trace",     "--html", "--r1",   "--r2",   "--tsp-solver",  "--alpha",      "--beta"}) {
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
  }
}

}  // namespace
}  // namespace hullinspect::testing
