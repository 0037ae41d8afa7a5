// The separation rule as the simulator counts it (docs/model.md §12), and the deconfliction
// layer's guarantee on hand-made standoffs.

#include <gtest/gtest.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/sim/deconfliction.hpp"
#include "hullinspect/sim/simulator.hpp"

namespace hullinspect::sim {
namespace {

using grid::Cell;

// A w × h all-hull world without corrosion, two UAVs at `a` and `b`, separation `d`.
struct TwoUavs {
  world::HullMask hull;
  world::Instance instance;
  world::MissionParams params;
  TwoUavs(int w, int h, Cell a, Cell b, int d) : hull(grid::Grid<std::uint8_t>(w, h, 1), "test") {
    instance.truth = grid::Grid<std::int8_t>(w, h, 0);
    instance.prior = grid::Grid<std::int8_t>(w, h, 0);
    params.uavs = 2;
    params.s1 = 1;
    params.s2 = 3;
    params.starts = {a, b};
    params.separation = d;
  }
};

TEST(SeparationRule, ChebyshevDistanceBelowDIsAConflictWhateverThePlanes) {
  TwoUavs w(20, 10, {2, 2}, {5, 2}, 3);
  Simulator sim(w.hull, w.instance, w.params);
  EXPECT_EQ(sim.separation_conflicts(), 0);
  EXPECT_EQ(sim.min_separation(), 3);
  // UAV 1 changes plane while UAV 0 moves to (3, 2): 2 cells from (5, 2), less than D = 3.
  sim.step(std::vector<Action>{Action::kEast, Action::kChangePlane});
  EXPECT_EQ(sim.separation_conflicts(), 1);
  EXPECT_EQ(sim.min_separation(), 2);
  sim.step(std::vector<Action>{Action::kNorth, Action::kHover});  // (3, 3) vs (5, 2): still 2
  EXPECT_EQ(sim.separation_conflicts(), 2);
}

TEST(SeparationRule, AnExchangeOfCellsIsAConflictAtOne) {
  TwoUavs w(20, 10, {2, 2}, {3, 2}, 1);
  Simulator sim(w.hull, w.instance, w.params);
  sim.step(std::vector<Action>{Action::kEast, Action::kWest});
  EXPECT_EQ(sim.separation_conflicts(), 1);
  EXPECT_EQ(sim.min_separation(), 0);
}

TEST(SeparationRule, NothingIsMeasuredWithoutSeparation) {
  TwoUavs w(20, 10, {2, 2}, {3, 2}, 0);
  Simulator sim(w.hull, w.instance, w.params);
  sim.step(std::vector<Action>{Action::kEast, Action::kWest});
  EXPECT_EQ(sim.separation_conflicts(), 0);
  EXPECT_FALSE(sim.min_separation().has_value());
}

TEST(SeparationRule, StrictSeparationMakesAConflictAMissionError) {
  TwoUavs w(20, 10, {2, 2}, {4, 2}, 2);
  w.params.strict_separation = true;
  Simulator sim(w.hull, w.instance, w.params);
  EXPECT_THROW(sim.step(std::vector<Action>{Action::kEast, Action::kHover}), LogicError);
}

TEST(Deconfliction, HeadOnUavsPassWithoutConflict) {
  for (int d = 1; d <= 3; ++d) {
    SCOPED_TRACE(d);
    TwoUavs w(30, 12, {5, 6}, {5 + d + 1, 6}, d);
    Simulator sim(w.hull, w.instance, w.params);
    Deconfliction layer(d, 2, 30, 12, nullptr);
    // Each wants the other's start: a head-on standoff on one row.
    const Cell goal[2] = {{5 + d + 1, 6}, {5, 6}};
    bool arrived = false;
    for (int t = 0; t < 100 && !arrived; ++t) {
      std::vector<Action> actions = {step_towards(sim.uavs()[0].pos, goal[0]),
                                     step_towards(sim.uavs()[1].pos, goal[1])};
      layer.adjust(sim, actions);
      sim.step(actions);
      arrived = sim.uavs()[0].pos == goal[0] && sim.uavs()[1].pos == goal[1];
    }
    EXPECT_TRUE(arrived);
    EXPECT_EQ(sim.separation_conflicts(), 0);
  }
}

}  // namespace
}  // namespace hullinspect::sim
