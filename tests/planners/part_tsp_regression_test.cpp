// Missions that once failed, kept so they never fail again.

#include <gtest/gtest.h>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/mission_checker.hpp"

namespace hullinspect::planners {
namespace {

TEST(PartTspRegression, ExactSolverNeverStopsAMission) {
  // The exact solver's branch-and-cut once stopped with "no fractional edge to branch on" in this
  // mission (found by the paper-quick preset) and handed the instance to the DFJ reference; the
  // root cause is fixed (docs/tsp.md) and no solve may fall back.
  MissionSpec spec;
  spec.algorithm = "part-tsp";
  spec.params.uavs = 8;
  spec.params.s2 = 7;
  spec.seed = 1;
  spec.corrosion = world::scenario("combined").corrosion(230);
  testing::MissionChecker checker;
  MissionOptions options;
  options.observers = {&checker};
  const auto r = run_mission(spec, world::default_hull(), options);
  EXPECT_TRUE(r.complete);
  EXPECT_TRUE(checker.ok());
  EXPECT_GT(r.planner.tsp_solves, 0);
  EXPECT_EQ(r.planner.tsp_fallbacks, 0);
}

}  // namespace
}  // namespace hullinspect::planners
