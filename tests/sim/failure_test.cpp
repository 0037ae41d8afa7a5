// UAV failures (docs/model.md, "Failures"): exact timing, in-transit failures, the seeded failure
// draws and their independence from the planner.

#include <gtest/gtest.h>

#include <set>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/sim/simulator.hpp"
#include "hullinspect/world/failures.hpp"
#include "support/printers.hpp"

namespace hullinspect::sim {
namespace {

using grid::Cell;

struct Strip {
  world::HullMask hull{grid::Grid<std::uint8_t>(40, 3, 1), "test"};
  world::Instance instance;
  world::MissionParams params;
  explicit Strip(int uavs) {
    instance.truth = grid::Grid<std::int8_t>(40, 3, 0);
    instance.prior = grid::Grid<std::int8_t>(40, 3, 0);
    params.uavs = uavs;
    params.s1 = 1;
    params.s2 = 3;
    for (int k = 0; k < uavs; ++k) params.starts.push_back({1 + 10 * k, 1});
  }
};

TEST(FailureTiming, TheActionOfTheFailureStepIsIgnoredAndNothingIsSensedAfterIt) {
  Strip w(1);
  Simulator sim(w.hull, w.instance, w.params);
  sim.fail_uav_at(0, 3);
  const std::vector<Action> east = {Action::kEast};
  for (int t = 0; t < 3; ++t) {
    sim.step(east);  // steps 0, 1, 2 are applied and sensed
    EXPECT_FALSE(sim.uavs()[0].failed) << "t = " << sim.time();
    EXPECT_FALSE(sim.view().sensed.readings(0).empty());
  }
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{4, 1}));
  const int known = sim.known_cells();
  EXPECT_FALSE(sim.finished());
  sim.step(east);  // step 3: the failure takes effect at its start
  EXPECT_TRUE(sim.uavs()[0].failed);
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{4, 1}));
  EXPECT_EQ(sim.applied_actions()[0], Action::kHover);
  EXPECT_TRUE(sim.view().sensed.readings(0).empty());
  EXPECT_EQ(sim.known_cells(), known);
  // The only UAV failed: nobody can act, the mission ends incomplete.
  EXPECT_TRUE(sim.finished());
  EXPECT_FALSE(sim.complete());
  const auto r = sim.result();
  EXPECT_FALSE(r.complete);
  EXPECT_FALSE(r.t_m.has_value());
  EXPECT_EQ(r.failed_uavs, 1);
  EXPECT_EQ(r.uavs[0].failed_at, 3);
  EXPECT_EQ(r.uavs[0].moves, 3);
}

TEST(FailureTiming, AUavFailingInTransitStaysInTransit) {
  Strip w(2);
  w.params.s1 = 1;
  w.params.s2 = 7;  // u_z = 3 with theta = 90
  w.hull = world::HullMask(grid::Grid<std::uint8_t>(40, 9, 1), "test");
  w.instance.truth = grid::Grid<std::int8_t>(40, 9, 0);
  w.instance.prior = grid::Grid<std::int8_t>(40, 9, 0);
  w.params.starts = {{3, 4}, {30, 4}};
  Simulator sim(w.hull, w.instance, w.params);
  ASSERT_EQ(sim.plane_change_steps(), 3);
  sim.fail_uav_at(0, 1);
  sim.step(std::vector<Action>{Action::kChangePlane, Action::kHover});  // step 0: starts descending
  EXPECT_TRUE(sim.uavs()[0].in_transit());
  for (int i = 0; i < 10; ++i) sim.step(std::vector<Action>{Action::kHover, Action::kWest});
  EXPECT_TRUE(sim.uavs()[0].failed);
  EXPECT_TRUE(sim.uavs()[0].in_transit());
  EXPECT_EQ(sim.uavs()[0].transit_left, 2);
  EXPECT_EQ(sim.uavs()[0].z, 2);
  EXPECT_TRUE(sim.view().sensed.readings(0).empty());
  EXPECT_FALSE(sim.finished());  // UAV 1 still works
  EXPECT_EQ(sim.result().failed_uavs, 1);
}

TEST(FailureTiming, FailureAtStepZeroFreezesTheUavBeforeItsFirstAction) {
  Strip w(2);
  Simulator sim(w.hull, w.instance, w.params);
  sim.fail_uav_at(1, 0);
  sim.step(std::vector<Action>{Action::kEast, Action::kEast});
  EXPECT_EQ(sim.uavs()[1].pos, (Cell{11, 1}));
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{2, 1}));
  EXPECT_EQ(sim.result().uavs[1].failed_at, 0);
}

TEST(FailureTimes, FixedFailuresTakeTheEarliestPerUav) {
  world::FailurePlan plan;
  plan.at = {{1, 50}, {1, 20}, {3, 0}};
  const auto t = world::failure_times(plan, 4, 7, 1000);
  EXPECT_EQ(t, (std::vector<int>{-1, 20, -1, 0}));
  EXPECT_EQ(plan.text(), "1@50,1@20,3@0");
  // A failure at or beyond the time limit never happens.
  EXPECT_EQ(world::failure_times(plan, 4, 7, 20), (std::vector<int>{-1, -1, -1, 0}));
}

TEST(FailureTimes, RandomFailuresDependOnTheSeedAloneAndMatchTheRate) {
  world::FailurePlan plan;
  plan.rate = 0.01;
  EXPECT_EQ(world::failure_times(plan, 8, 42, 20000), world::failure_times(plan, 8, 42, 20000));
  EXPECT_NE(world::failure_times(plan, 8, 42, 20000), world::failure_times(plan, 8, 43, 20000));
  // A UAV's draw does not depend on the fleet size (one stream per UAV).
  const auto four = world::failure_times(plan, 4, 42, 20000);
  const auto eight = world::failure_times(plan, 8, 42, 20000);
  EXPECT_TRUE(std::equal(four.begin(), four.end(), eight.begin()));
  // Geometric with p = 0.01: mean (1 − p)/p = 99 steps.
  double sum = 0;
  int count = 0;
  for (std::uint64_t seed = 1; seed <= 500; ++seed) {
    for (int t : world::failure_times(plan, 4, seed, 1 << 30)) {
      ASSERT_GE(t, 0);
      sum += t;
      ++count;
    }
  }
  EXPECT_NEAR(sum / count, 99.0, 6.0);
}

TEST(FailureTimes, OneRandomFailureHitsExactlyOneUavWithinTheHorizon) {
  world::FailurePlan plan;
  plan.one_within = 300;
  std::set<int> uavs;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const auto t = world::failure_times(plan, 5, seed, 20000);
    int failed = 0;
    for (int k = 0; k < 5; ++k) {
      if (t[static_cast<std::size_t>(k)] < 0) continue;
      ++failed;
      uavs.insert(k);
      EXPECT_LT(t[static_cast<std::size_t>(k)], 300);
    }
    EXPECT_EQ(failed, 1);
  }
  EXPECT_EQ(uavs.size(), 5u);
}

TEST(FailurePlanText, ParsesAndRejects) {
  const auto f = world::parse_uav_failure("2@150");
  EXPECT_EQ(f.uav, 2);
  EXPECT_EQ(f.time, 150);
  for (const char* bad : {"2", "2@", "@3", "a@3", "2@-1", "2@3x"}) {
    try {
      world::parse_uav_failure(bad);
      ADD_FAILURE() << bad;
    } catch (const ParameterError& e) {
      EXPECT_EQ(e.name(), "fail");
      EXPECT_EQ(e.problem(),
                std::string("expects UAV@STEP with two integers >= 0 (got '") + bad + "')");
    }
  }
  world::FailurePlan plan;
  plan.at = {{4, 1}};
  try {
    world::validate(plan, 4);
    ADD_FAILURE();
  } catch (const ParameterError& e) {
    EXPECT_STREQ(e.what(), "fail: UAV 4 does not exist (the fleet has UAVs 0 to 3)");
  }
  plan = {};
  plan.rate = 1.5;
  EXPECT_THROW(world::validate(plan, 4), ParameterError);
}

}  // namespace
}  // namespace hullinspect::sim
