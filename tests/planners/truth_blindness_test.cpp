// Every registered planner, whatever it is, cannot reach the ground truth C.

#include <gtest/gtest.h>

#include "hullinspect/planners/planner.hpp"
#include "support/truth_blindness.hpp"

namespace hullinspect::planners {
namespace {

TEST(TruthBlindness, EveryRegisteredPlannerDecidesOnlyFromWhatWasSensed) {
  world::MissionParams params;
  params.uavs = 4;
  for (const auto& info : planner_registry()) {
    if (info.sees_truth) continue;  // an oracle (a bound): the next test
    testing::TruthBlindnessReport report;
    EXPECT_TRUE(testing::planner_is_truth_blind(info.name, {}, params, 5, &report)) << info.name;
    EXPECT_GE(report.first_differing_reading, 1) << info.name;  // the two missions did diverge
  }
}

// The prior-aware partition (with and without the scenario's statistics) on every partitioned
// planner: weights come from the prior and the statistics, never from C.
TEST(TruthBlindness, PriorWeightedPartitionsAreTruthBlind) {
  world::MissionParams params;
  params.uavs = 4;
  for (const char* algorithm : {"lawnmower", "part-tsp", "part-tsp0", "sweep-inspect"}) {
    for (const auto& options :
         {OptionMap{{"prior-weights", "true"}},
          OptionMap{{"prior-weights", "true"}, {"prior-statistics", "false"}}}) {
      testing::TruthBlindnessReport report;
      EXPECT_TRUE(testing::planner_is_truth_blind(algorithm, options, params, 6, &report))
          << algorithm;
      EXPECT_GE(report.first_differing_reading, 1) << algorithm;
    }
  }
}

// The check can tell: a registered oracle, which reads C by design, is caught by it.
TEST(TruthBlindness, TheCheckCatchesEveryOracle) {
  world::MissionParams params;
  params.uavs = 4;
  int oracles = 0;
  for (const auto& info : planner_registry()) {
    if (!info.sees_truth) continue;
    ++oracles;
    EXPECT_FALSE(testing::planner_is_truth_blind(info.name, {}, params, 5)) << info.name;
  }
  EXPECT_GE(oracles, 1);
}

}  // namespace
}  // namespace hullinspect::planners
