// Sweep-Inspect's own battery returns (planners/sweep_returns.hpp) on an open 30 × 25 grid with
// one launch site at (0, 0): the sortie ends at the foot of a band that climbs away from the
// site, not at its top where the sortie layer would act; it goes on down a band that flies
// towards the site; it goes on when the battery lasts to the route's end, or is far from empty;
// never without a limited battery.
#include "hullinspect/planners/sweep_returns.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace hullinspect::planners {
namespace {

using grid::Cell;

// Take-off 1 step, no transfer, plane change 1 step; 200 steps per battery, reserve 10, swap 20,
// margin 3: the layer needs flight home (Manhattan to (0, 0) + 1) + 13 where a UAV is, on z = 2.
struct OneSite {
  world::LaunchLegs legs;
  world::BatterySteps battery{true, 200, 10, 20};
  grid::DistanceService flights{30, 25};
  OneSite() {
    legs.sites = {{0, 0}};
    legs.site_of = {0};
    legs.outbound = {0};
    legs.takeoff_steps = 1;
    legs.plane_change_steps = 1;
    grid::Grid<int> home(30, 25, 0);
    for (int y = 0; y < 25; ++y)
      for (int x = 0; x < 30; ++x) home(x, y) = x + y;
    legs.flight_home = {home};
  }
  sim::ReturnRule rule() const { return {legs, battery, 3}; }
};

// The band up column 10 from its foot, then across and down column 13.
const std::vector<Cell> kUpAndDown{{10, 20}, {13, 20}, {13, 0}};

TEST(SweepReturns, EndsTheSortieAtTheFootOfABandClimbingAway) {
  OneSite w;
  // At (10, 0) with 60 left: the layer needs 24 here, and would act near (10, 18) (needs 42
  // there with 42 left), 36 cells further from the site.
  const SortieRoute route{0, {10, 0}, 2, 60, kUpAndDown};
  EXPECT_TRUE(end_sortie_now(route, w.rule(), w.flights));
}

TEST(SweepReturns, GoesOnWhenTheBatteryLastsToTheRouteEnd) {
  OneSite w;
  // The band up column 10 alone: with 90 left it ends at (10, 20) with 70, 26 more than needed
  // there; with 60 the layer would act at (10, 18) and the foot is the cheaper end.
  const std::vector<Cell> up{{10, 20}};
  EXPECT_FALSE(end_sortie_now({0, {10, 0}, 2, 90, up}, w.rule(), w.flights));
  EXPECT_TRUE(end_sortie_now({0, {10, 0}, 2, 60, up}, w.rule(), w.flights));
}

TEST(SweepReturns, GoesOnDownABandFlyingTowardsTheSite) {
  OneSite w;
  // At the top of column 13 with the layer's point 10 cells down: each step down brings it
  // nearer home at no cost in unused battery.
  const std::vector<Cell> down{{13, 0}, {16, 0}, {16, 20}};
  EXPECT_FALSE(end_sortie_now({0, {13, 20}, 2, 60, down}, w.rule(), w.flights));
}

TEST(SweepReturns, GoesOnWhileTheBatteryIsFarFromItsEnd) {
  OneSite w;
  // 150 left at (10, 0): 126 beyond what the layer needs, over a third of the endurance.
  const std::vector<Cell> long_route{{10, 20}, {13, 20}, {13, 0}, {16, 0}, {16, 24}, {29, 24}};
  EXPECT_FALSE(end_sortie_now({0, {10, 0}, 2, 150, long_route}, w.rule(), w.flights));
}

TEST(SweepReturns, NeverWithoutALimitedBattery) {
  OneSite w;
  w.battery.limited = false;
  EXPECT_FALSE(w.rule().limited());
  EXPECT_FALSE(end_sortie_now({0, {10, 0}, 2, 60, kUpAndDown}, w.rule(), w.flights));
  EXPECT_FALSE(end_sortie_now({0, {10, 0}, 2, -1, kUpAndDown}, sim::ReturnRule{}, w.flights));
}

TEST(SweepReturns, NowWhenTheLayerWouldActNow) {
  OneSite w;
  EXPECT_TRUE(end_sortie_now({0, {10, 0}, 2, 23, kUpAndDown}, w.rule(), w.flights));
}

// The weight of a step of unused battery: (round trip + swap) / (endurance − reserve − margin −
// round trip) from (10, 0): (22 + 20) / (200 − 13 − 22).
TEST(SweepReturns, UnusedBatteryIsWeighedBySwapsItCosts) {
  OneSite w;
  EXPECT_DOUBLE_EQ(unused_battery_weight({0, {10, 0}, 2, 60, kUpAndDown}, w.rule()), 42.0 / 165.0);
}

}  // namespace
}  // namespace hullinspect::planners
