// Sweep-Inspect's long prior tours (more than SweepInspectPlanner's kReplannedTourCells cells,
// more than kExhaustiveTourPoints planned over neighbour lists) are repaired as their cells are
// seen: with one or two UAVs on a 600 × 60 hull each UAV's prior holds several hundred cells, and
// the missions complete under the checker and end the tours (T_c) sooner than nearest-first.

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

int summed_t_c(int n, bool planned) {
  int total = 0;
  for (std::uint64_t seed : {1, 2, 3}) {
    MissionSpec spec;
    spec.algorithm = "sweep-inspect";
    spec.planner_options = {{"plan-prior-tour", planned ? "true" : "false"}};
    spec.params.uavs = n;
    spec.params.s2 = 7;
    spec.params.time_limit = 100'000;
    spec.corrosion = world::scenario("perfect").corrosion(long_hull().width());
    spec.seed = seed;
    testing::MissionChecker checker;
    MissionOptions options;
    options.observers = {&checker};
    const sim::MissionResult r = run_mission(spec, long_hull(), options);
    SCOPED_TRACE(::testing::Message() << "n=" << n << " seed=" << seed << " planned=" << planned);
    EXPECT_TRUE(r.complete);
    EXPECT_TRUE(checker.ok());
    total += r.t_c.value_or(1'000'000);
  }
  return total;
}

TEST(PriorTourRepair, LongToursEndSoonerThanNearestFirst) {
  for (int n : {1, 2}) {
    EXPECT_LT(summed_t_c(n, true), summed_t_c(n, false)) << "n = " << n;
  }
}

}  // namespace
}  // namespace hullinspect::planners
