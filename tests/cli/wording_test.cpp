// Counted nouns in what the commands print agree with their counts ("1 UAV", "2 UAVs").

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/cli_runner.hpp"

namespace hullinspect::testing {
namespace {

TEST(Wording, OneUavIsSingular) {
  const auto plan = run_cli({"plan", "--uavs", "1", "--seed", "1"});
  ASSERT_EQ(plan.status, 0) << plan.err;
  EXPECT_EQ(plan.out.substr(0, plan.out.find('\n')),
            "lawnmower with 1 UAV, s1 = 5, s2 = 7, seed 1: planned on an empty prior (pure "
            "coverage: no corrosion expected)");
  const auto starts = run_cli({"run", "--uavs", "1", "--start", "1,1", "--start", "2,2"});
  EXPECT_EQ(starts.status, 2);
  EXPECT_EQ(starts.err, "hullinspect: --start: gives 2 start cells for 1 UAV\n");
}

TEST(Wording, ExperimentDryRunCountsOneOfEach) {
  const auto dir = make_temp_dir("wording");
  const std::string config = dir + "/one.yaml";
  std::ofstream(dir + "/hull.txt") << "XXXXXXXXXXXX\nXXXXXXXXXXXX\nXXXXXXXXXXXX\n";
  // `hullinspect experiment --dry-run --config <config> <extra...>` prints exactly `expected`.
  const auto expect_dry_run = [&](std::vector<std::string> extra, const std::string& expected) {
    std::vector<std::string> args = {"experiment", "--dry-run", "--config", config};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = run_cli(args);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, expected);
  };
  std::ofstream(config) << "name: one\nhull: hull.txt\nscenarios: [perfect]\ns2: 7\nuavs: 1\n"
                           "algorithms: [lawnmower]\ninstances: 1\n";
  expect_dry_run({},
                 "one: 1 scenario × 1 s2 × 1 fleet size × 1 algorithm = 1 cell; × 1 instance "
                 "(seed 1) = 1 run (1 in shard 1/1)\n");
  std::ofstream(config) << "name: two\nhull: hull.txt\nscenarios: [perfect, imperfect]\n"
                           "s2: [7, 9]\nuavs: [1, 2]\nalgorithms: [lawnmower, part-tsp]\n"
                           "instances: 2\n";
  expect_dry_run({},
                 "two: 2 scenarios × 2 s2 × 2 fleet sizes × 2 algorithms = 16 cells; × 2 "
                 "instances (seeds 1–2) = 32 runs (32 in shard 1/1)\n");
  expect_dry_run({"--instances", "200", "--first-seed", "3000000"},
                 "two: 2 scenarios × 2 s2 × 2 fleet sizes × 2 algorithms = 16 cells; × 200 "
                 "instances (seeds 3000000–3000199) = 3200 runs (3200 in shard 1/1)\n");
  std::ofstream(config) << "name: listed\nhull: hull.txt\nscenarios: [perfect]\ns2: 7\nuavs: 1\n"
                           "algorithms: [lawnmower]\ninstances: [7, 3, 11, 4]\n";
  expect_dry_run({},
                 "listed: 1 scenario × 1 s2 × 1 fleet size × 1 algorithm = 1 cell; × 4 "
                 "instances (seeds 7, 3, 11, …) = 4 runs (4 in shard 1/1)\n");
  // The largest seed and 0 are not a range (seed + 1 wraps round).
  std::ofstream(config) << "name: edge\nhull: hull.txt\nscenarios: [perfect]\ns2: 7\nuavs: 1\n"
                           "algorithms: [lawnmower]\ninstances: [18446744073709551615, 0]\n";
  expect_dry_run({},
                 "edge: 1 scenario × 1 s2 × 1 fleet size × 1 algorithm = 1 cell; × 2 "
                 "instances (seeds 18446744073709551615, 0) = 2 runs (2 in shard 1/1)\n");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hullinspect::testing
