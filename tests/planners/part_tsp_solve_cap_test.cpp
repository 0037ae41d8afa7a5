// Part-TSP's cap on the segments one solve sees (tsp-max-segments): a plan over more segments is
// ordered by the local search instead of the configured solver, and the mission still completes.

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/part_tsp_planner.hpp"
#include "part_tsp_test_support.hpp"
#include "support/mission_checker.hpp"

namespace hullinspect::testing {
namespace {

/// The reference solver, remembering the largest problem it was given.
class SizeRecordingTsp final : public tsp::TspSolver {
 public:
  explicit SizeRecordingTsp(int* largest) : largest_(largest) {}
  tsp::TspSolution solve(const tsp::SegmentTsp& p) override {
    *largest_ = std::max(*largest_, static_cast<int>(p.segments.size()));
    return reference_.solve(p);
  }

 private:
  int* largest_;
  ReferenceSegmentTsp reference_;
};

// 60 × 12, one UAV, a perfect prior with 10 corroded cells in separate columns spread over the
// close-up strips: the first plan at z = 1 has one segment per cell (10: the reference solver is
// exact up to 10).
HandInstance scattered_spots() {
  std::vector<std::string> rows(12, std::string(60, '0'));
  for (int i = 0; i < 10; ++i) rows[static_cast<std::size_t>((i * 5) % 12)][6 * i + 2] = '1';
  return hand_instance(rows, rows);
}

struct Outcome {
  int largest_solve = 0;
  sim::MissionResult result;
  sim::PlannerStats stats;
};

Outcome fly(int cap) {
  const HandInstance h = scattered_spots();
  Outcome out;
  planners::PartTspOptions o;
  o.partitioner = "stripes";
  o.tsp_max_segments = cap;
  planners::PartTspPlanner planner(o, std::make_unique<SizeRecordingTsp>(&out.largest_solve));
  world::MissionParams params;
  params.uavs = 1;
  params.s1 = 3;
  params.s2 = 5;
  params.starts = {{30, 6}};
  params.time_limit = 5000;
  MissionChecker checker;
  planners::MissionOptions mo;
  mo.observers = {&checker};
  out.result = planners::run_mission(h.hull, h.instance, params, planner, mo);
  out.stats = planner.stats();
  EXPECT_TRUE(checker.ok());
  return out;
}

TEST(PartTspSolveCap, NoSolveOfTheConfiguredSolverSeesMoreSegmentsThanTheCap) {
  const Outcome uncapped = fly(0);
  ASSERT_TRUE(uncapped.result.complete);
  ASSERT_GT(uncapped.largest_solve, 5) << "the instance must need a plan above the cap";
  EXPECT_EQ(uncapped.stats.tsp_unproven, 0);

  const Outcome capped = fly(5);
  EXPECT_TRUE(capped.result.complete);
  EXPECT_LE(capped.largest_solve, 5);
  // The plans above the cap came from the local search, which proves nothing.
  EXPECT_GT(capped.stats.tsp_unproven, 0);
  EXPECT_GE(capped.stats.tsp_solves, uncapped.stats.tsp_solves - capped.stats.tsp_unproven);
}

TEST(PartTspSolveCap, PlansAtOrBelowTheCapAreTheConfiguredSolversAsBefore) {
  const Outcome uncapped = fly(0);
  const Outcome capped = fly(uncapped.largest_solve);
  EXPECT_EQ(capped.largest_solve, uncapped.largest_solve);
  EXPECT_EQ(capped.stats.tsp_unproven, 0);
  EXPECT_EQ(capped.result.t_m, uncapped.result.t_m);
  EXPECT_EQ(capped.result.uavs.front().moves, uncapped.result.uavs.front().moves);
}

}  // namespace
}  // namespace hullinspect::testing
