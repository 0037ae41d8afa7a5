// Sweep-Inspect's long prior tours (more than SweepInspectPlanner's kReplannedTourCells cells,
// more than kExhaustiveTourPoints planned over neighbour lists) are repaired as their cells are
// seen: with one or two UAVs on a 600 × 60 hull each UAV's prior holds several hundred cells, and
// the missions complete under the checker, the tours ending (T_c) before the sweeps (T_m).

#include <gtest/gtest.h>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/mission_checker.hpp"

namespace hullinspect::planners {
namespace {

// A rectangle four times the default hull's area: priors long enough to be repaired.
const world::HullMask& long_hull() {
  static const world::HullMask hull = [] {
    std::string rows;
    for (int y = 0; y < 60; ++y) rows += std::string(600, 'X') + "\n";
    return world::parse_text_mask(rows, "600x60");
  }();
  return hull;
}

void expect_tours_complete(int n) {
  for (std::uint64_t seed : {1, 2, 3}) {
    MissionSpec spec;
    spec.algorithm = "sweep-inspect";
    spec.params.uavs = n;
    spec.params.s2 = 7;
    spec.params.time_limit = 100'000;
    spec.corrosion = world::scenario("perfect").corrosion(long_hull().width());
    spec.seed = seed;
    testing::MissionChecker checker;
    MissionOptions options;
    options.observers = {&checker};
    const sim::MissionResult r = run_mission(spec, long_hull(), options);
    SCOPED_TRACE(::testing::Message() << "n=" << n << " seed=" << seed);
    ASSERT_TRUE(r.complete);
    EXPECT_TRUE(checker.ok());
    EXPECT_LT(*r.t_c, *r.t_m);
  }
}

TEST(PriorTourRepair, LongToursComplete) {
  for (int n : {1, 2}) expect_tours_complete(n);
}

}  // namespace
}  // namespace hullinspect::planners
