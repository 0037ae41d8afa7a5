// `hullinspect tsp` end to end through the built binary.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include "hullinspect/io/tsp_json.hpp"
#include "support/cli_runner.hpp"
#include "support/tsp_checker.hpp"

namespace hullinspect::testing {
namespace {

std::string write_file(const std::string& dir, const std::string& name, const std::string& text) {
  const std::string path = dir + "/" + name;
  std::ofstream(path) << text;
  return path;
}

tsp::TspSolution solution_of(const std::string& out) {
  const auto j = nlohmann::json::parse(out);
  tsp::TspSolution s;
  s.length = j.at("length").get<long long>();
  s.optimal = j.at("optimal").get<bool>();
  s.seconds = j.at("seconds").get<double>();
  for (const auto& v : j.at("order")) {
    s.order.push_back({v.at("segment").get<int>(), v.at("reversed").get<bool>()});
  }
  return s;
}

TEST(TspCommand, EverySolverPrintsAValidTour) {
  const auto dir = make_temp_dir("tsp-cli");
  const tsp::SegmentTsp problem = random_strip_instance(7, 3);
  const std::string file = write_file(dir, "p.json", io::tsp_instance_json(problem).dump());
  const long long optimum = brute_force_length(problem);
  for (const std::string solver : {"exact", "dfj-iterative", "cbc-cut", "heuristic"}) {
    SCOPED_TRACE(solver);
    const auto r = run_cli({"tsp", "--solver", solver, file});
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    ASSERT_EQ(r.out.back(), '\n');
    const auto s = solution_of(r.out);
    EXPECT_TRUE(valid_solution(problem, s));
    EXPECT_GE(s.seconds, 0.0);
    if (solver != "heuristic") {
      EXPECT_TRUE(s.optimal);
      EXPECT_EQ(s.length, optimum);
    } else {
      EXPECT_GE(s.length, optimum);
    }
  }
  // The default solver is exact.
  const auto r = run_cli({"tsp", file});
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(solution_of(r.out).length, optimum);
  std::filesystem::remove_all(dir);
}

TEST(TspCommand, TimeLimitGivesAnUnprovenValidTour) {
  const auto dir = make_temp_dir("tsp-cli-limit");
  const tsp::SegmentTsp problem = random_strip_instance(40, 5, 230, 30, 60);
  const std::string file = write_file(dir, "p.json", io::tsp_instance_json(problem).dump());
  const auto r = run_cli({"tsp", "--solver", "exact", "--time-limit", "0.000001", file});
  EXPECT_EQ(r.status, 0) << r.err;
  const auto s = solution_of(r.out);
  EXPECT_TRUE(valid_solution(problem, s));
  EXPECT_FALSE(s.optimal);
  std::filesystem::remove_all(dir);
}

TEST(TspCommand, SolverOptions) {
  const auto dir = make_temp_dir("tsp-cli-options");
  const tsp::SegmentTsp problem = random_strip_instance(12, 8);
  const std::string file = write_file(dir, "p.json", io::tsp_instance_json(problem).dump());
  const auto a = run_cli({"tsp", "--solver", "heuristic", "-O", "kicks=0", "-O", "seed=3", file});
  EXPECT_EQ(a.status, 0) << a.err;
  EXPECT_TRUE(valid_solution(problem, solution_of(a.out)));
  const auto b = run_cli({"tsp", "-O", "dp-max-segments=0", file});
  EXPECT_EQ(b.status, 0) << b.err;
  EXPECT_TRUE(solution_of(b.out).optimal);
  std::filesystem::remove_all(dir);
}

struct BadInput {
  std::vector<std::string> args;  // FILE stands for a valid instance file
  std::string file_text;          // written to bad.json when not empty
  std::string message;            // the whole stderr line; BAD stands for bad.json's path
};

class TspCommandBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(TspCommandBadInput, OneLineOnStderrExitTwo) {
  const auto dir = make_temp_dir("tsp-cli-bad");
  const std::string good =
      write_file(dir, "good.json", R"({"start":[0,0],"segments":[[[1,0],[4,0]]]})");
  const std::string bad = dir + "/bad.json";
  if (!GetParam().file_text.empty()) write_file(dir, "bad.json", GetParam().file_text);
  std::vector<std::string> args = {"tsp"};
  for (const auto& a : GetParam().args) {
    args.push_back(a == "FILE" ? good : a == "BAD" ? bad : a);
  }
  const auto r = run_cli(args);
  std::string message = GetParam().message;
  if (auto at = message.find("BAD"); at != std::string::npos) message.replace(at, 3, bad);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, message + "\n");
  EXPECT_EQ(r.out, "");
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(
    Table, TspCommandBadInput,
    ::testing::Values(
        BadInput{{"BAD"},
                 R"({"start":[0,0],"segments":[[[1,0],[4,0]],[[1,0],[4]]]})",
                 "hullinspect: BAD: segments[1][1]: expected [x, y] integers"},
        BadInput{{"BAD"},
                 R"({"start":[0,0]})",
                 R"(hullinspect: BAD: missing "segments": [[[x1, y1], [x2, y2]], ...])"},
        BadInput{{"BAD"}, "", "hullinspect: BAD: cannot open the file"},
        BadInput{{"--solver", "lkh", "FILE"},
                 "",
                 "hullinspect: --solver: unknown TSP solver 'lkh' (known: exact, dfj-iterative, "
                 "cbc-cut, heuristic)"},
        BadInput{
            {"--time-limit", "-1", "FILE"},
            "",
            "hullinspect: --time-limit: must be a number in [0, 1e+09] (got '-1') (see --help)"},
        BadInput{
            {"-O", "kicks", "FILE"}, "", "hullinspect: --option: expects KEY=VALUE (got 'kicks')"},
        BadInput{{"--solver", "heuristic", "-O", "kicks=many", "FILE"},
                 "",
                 "hullinspect: --option: heuristic.kicks: must be an integer in [0, 1000000] (got "
                 "'many')"},
        BadInput{{"--solver", "dfj-iterative", "-O", "dp-max-segments=3", "FILE"},
                 "",
                 "hullinspect: --option: dfj-iterative.dp-max-segments: unknown option (known: "
                 "time-limit)"}));

}  // namespace
}  // namespace hullinspect::testing
