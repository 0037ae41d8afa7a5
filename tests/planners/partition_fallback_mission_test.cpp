// Missions count the DARP → transfer partition fallback (PlannerStats::partition_fallbacks,
// docs/model.md): 1 when DARP did not converge and the mission flew the transfer partition, else 0.

#include <gtest/gtest.h>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/mission_checker.hpp"

namespace hullinspect::planners {
namespace {

MissionSpec spec_for(const std::string& algorithm, const OptionMap& options) {
  MissionSpec spec;
  spec.algorithm = algorithm;
  spec.planner_options = options;
  spec.params.uavs = 6;
  spec.params.s2 = 7;
  spec.corrosion = world::scenario("perfect").corrosion(world::default_hull().width());
  spec.seed = 2;
  return spec;
}

TEST(PartitionFallbackMission, CountedOnlyWhenDarpDidNotConverge) {
  const OptionMap starved = {{"partitioner.iteration-limit", "1"},
                             {"partitioner.max-discrepancy", "0"}};
  for (const char* algorithm : {"lawnmower", "part-tsp"}) {
    SCOPED_TRACE(algorithm);
    testing::MissionChecker checker;
    MissionOptions options;
    options.observers = {&checker};
    const auto fell_back =
        run_mission(spec_for(algorithm, starved), world::default_hull(), options);
    EXPECT_EQ(fell_back.planner.partition_fallbacks, 1);
    EXPECT_TRUE(fell_back.complete);
    EXPECT_TRUE(checker.ok());
    const auto darp = run_mission(spec_for(algorithm, {}), world::default_hull());
    EXPECT_EQ(darp.planner.partition_fallbacks, 0);
    EXPECT_TRUE(darp.complete);
  }
  // Coop-Frontier does not partition.
  EXPECT_EQ(
      run_mission(spec_for("coop-frontier", {}), world::default_hull()).planner.partition_fallbacks,
      0);
}

}  // namespace
}  // namespace hullinspect::planners
