// Two UAVs that must pass each other where there is less than D of room beside them (docs/model.md,
// "The deconfliction layer", the lead): the one that waited keeps precedence long enough to get
// past, so the mission completes instead of ending at the time limit.

#include <gtest/gtest.h>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/mission_checker.hpp"

namespace hullinspect::planners {
namespace {

TEST(SeparationStandoff, PartTspFourUavsAtThreeCompletes) {
  // UAV 0 (westward along the top row) and UAV 1 (northward up column 57) must pass each other
  // in a corner with less than D of room: a precedence that ends at the first move would pass
  // between them forever.
  const auto& hull = world::default_hull();
  MissionSpec spec;
  spec.algorithm = "part-tsp";
  spec.seed = 1;
  spec.params.uavs = 4;
  spec.params.s2 = 9;
  spec.params.separation = 3;
  spec.params.time_limit = 3000;
  spec.corrosion = world::scenario("perfect").corrosion(hull.width());
  testing::MissionChecker checker;
  MissionOptions options;
  options.observers = {&checker};
  const auto r = run_mission(spec, hull, options);
  EXPECT_TRUE(checker.ok());
  EXPECT_TRUE(r.complete) << "m = " << r.m_percent(r.steps) << " at t = " << r.steps;
  EXPECT_EQ(r.separation_conflicts, 0);
}

}  // namespace
}  // namespace hullinspect::planners
