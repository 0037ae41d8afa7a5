// The plane-change FSM of Part-TSP (paper Fig. 3, model.md §5.3), clause by clause.

#include <gtest/gtest.h>

#include "hullinspect/planners/part_tsp_fsm.hpp"
#include "hullinspect/sim/types.hpp"

namespace hullinspect::planners::part_tsp {
namespace {

FsmDecision at(int z, int h, int unknown, int t_d, int t_i, int r1 = 2, int r2 = 0) {
  return evaluate_fsm(FsmInput{z, h, unknown, t_d, t_i}, r1, r2);
}

TEST(PartTspFsm, DescendsOnlyWithCorrosionAndAfterR1StepsWithoutDetection) {
  EXPECT_EQ(at(2, 0, 10, 50, 0), FsmDecision::kStay);  // nothing to inspect
  EXPECT_EQ(at(2, 3, 10, 0, 0), FsmDecision::kStay);   // t_d < r1
  EXPECT_EQ(at(2, 3, 10, 1, 0), FsmDecision::kStay);
  EXPECT_EQ(at(2, 3, 10, 2, 0), FsmDecision::kChangePlane);  // t_d = r1
  EXPECT_EQ(at(2, 3, 10, 9, 0), FsmDecision::kChangePlane);
  EXPECT_EQ(at(2, 3, 10, 0, 0, 0), FsmDecision::kChangePlane);  // r1 = 0: at once
}

TEST(PartTspFsm, DescendsAtOnceWhenNoUnknownCellIsLeft) {
  // The first completion clause: coverage is over, only inspection remains.
  EXPECT_EQ(at(2, 3, 0, 0, 0), FsmDecision::kChangePlane);
  EXPECT_EQ(at(2, 3, 0, 0, 0, 100), FsmDecision::kChangePlane);
}

TEST(PartTspFsm, AscendsWhenInspectionIsOverAfterR2Steps) {
  EXPECT_EQ(at(1, 2, 10, 0, 50), FsmDecision::kStay);        // still corrosion to inspect
  EXPECT_EQ(at(1, 0, 10, 0, 0), FsmDecision::kChangePlane);  // r2 = 0
  EXPECT_EQ(at(1, 0, 10, 0, 0, 2, 1), FsmDecision::kStay);   // t_i < r2
  EXPECT_EQ(at(1, 0, 10, 0, 1, 2, 1), FsmDecision::kChangePlane);
}

TEST(PartTspFsm, StaysDownWhenNoUnknownCellIsLeftAndIsDoneWhenNothingIsLeft) {
  // The second completion clause: nothing left to cover, so there is no reason to go up.
  EXPECT_EQ(at(1, 2, 0, 0, 9), FsmDecision::kStay);
  EXPECT_EQ(at(1, 0, 0, 0, 9), FsmDecision::kDone);
  EXPECT_EQ(at(2, 0, 0, 9, 9), FsmDecision::kDone);
}

TEST(PartTspFsm, TargetValues) {
  EXPECT_EQ(target_value(2, 0), sim::kUnknown);
  EXPECT_EQ(target_value(2, 5), sim::kUnknown);        // z = 2 always covers
  EXPECT_EQ(target_value(1, 5), sim::kCorrosionSeen);  // z = 1 inspects while h > 0
  EXPECT_EQ(target_value(1, 0), sim::kUnknown);        // ... and covers when r2 keeps it down
}

}  // namespace
}  // namespace hullinspect::planners::part_tsp
