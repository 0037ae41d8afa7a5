// Batteries (docs/model.md, "Batteries and sorties"): flight uses the battery, ground time does
// not, airborne with an empty battery is a crash, and a sortie return lands, swaps and flies the
// UAV back to where it left off.

#include <gtest/gtest.h>

#include <limits>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/sim/simulator.hpp"
#include "hullinspect/sim/sortie_layer.hpp"
#include "hullinspect/sim/uav_rules.hpp"
#include "hullinspect/world/battery.hpp"
#include "support/printers.hpp"
#include "support/strip_world.hpp"

namespace hullinspect::sim {
namespace {

using grid::Cell;

// The strip world with a launch site at (0, 0), a take-off of 1 s, 100 s per battery, a reserve
// of 5 s and a swap of 4 s.
struct Strip : testing::StripWorld {
  Strip() {
    params.launch_sites = {{0, 0}};
    params.takeoff_time_s = 1;
    params.endurance_s = 100;
    params.reserve_s = 5;
    params.swap_time_s = 4;
  }
};

TEST(Battery, FlightUsesItAndAnEmptyBatteryAirborneIsACrash) {
  Strip w;
  Simulator sim(w.hull, w.instance, w.params);
  EXPECT_FALSE(sim.uavs()[0].airborne);
  EXPECT_EQ(sim.uavs()[0].battery_left, 100);
  const std::vector<Action> hover = {Action::kHover};
  sim.step(hover);  // the take-off
  EXPECT_TRUE(sim.uavs()[0].airborne);
  EXPECT_EQ(sim.uavs()[0].battery_left, 99);
  while (sim.uavs()[0].battery_left > 0) sim.step(hover);
  EXPECT_EQ(sim.time(), 100);
  EXPECT_FALSE(sim.uavs()[0].failed);
  sim.step(hover);  // airborne with nothing left
  EXPECT_TRUE(sim.uavs()[0].failed);
  const MissionResult r = sim.result();
  EXPECT_EQ(r.battery_crashes, 1);
  EXPECT_EQ(r.failed_uavs, 1);
  EXPECT_TRUE(r.uavs[0].battery_crash);
  EXPECT_EQ(r.uavs[0].failed_at, 100);
  EXPECT_EQ(r.uavs[0].min_battery, 0);
  ASSERT_EQ(r.uavs[0].sorties.size(), 1u);
  EXPECT_EQ(r.uavs[0].sorties[0].takeoff, 0);
  EXPECT_EQ(r.uavs[0].sorties[0].landing, -1);
}

TEST(Battery, UnlimitedWithoutAnEndurance) {
  Strip w;
  w.params.endurance_s.reset();
  w.params.reserve_s.reset();
  w.params.swap_time_s = world::MissionParams{}.swap_time_s;
  Simulator sim(w.hull, w.instance, w.params);
  const std::vector<Action> hover = {Action::kHover};
  for (int t = 0; t < 200; ++t) sim.step(hover);
  EXPECT_FALSE(sim.uavs()[0].failed);
  EXPECT_EQ(sim.uavs()[0].battery_left, -1);
  EXPECT_EQ(sim.result().battery_crashes, 0);
  EXPECT_EQ(sim.result().uavs[0].flight_steps, 200);
}

TEST(Battery, ASortieReturnLandsSwapsAndFliesBackToWhereItLeftOff) {
  Strip w;
  Simulator sim(w.hull, w.instance, w.params);
  const std::vector<Action> hover = {Action::kHover};
  const std::vector<Action> down = {Action::kChangePlane};
  while (sim.uavs()[0].away_left > 0) sim.step(hover);  // take-off 1 + flight 7
  EXPECT_EQ(sim.time(), 8);
  sim.step(down);  // to plane 1 (u_z = 1 for s1 = 1, s2 = 3)
  ASSERT_EQ(sim.uavs()[0].z, 1);
  EXPECT_EQ(sim.uavs()[0].battery_left, 91);
  sim.return_for_swap(0);
  // Climb 1, flight 7, landing 1 = 9 home; swap 4; take-off 1, flight 7, descent 1 = 9 out.
  EXPECT_EQ(sim.uavs()[0].away_left, 22);
  for (int i = 0; i < 9; ++i) sim.step(hover);
  EXPECT_FALSE(sim.uavs()[0].airborne);
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{0, 0}));
  EXPECT_EQ(sim.uavs()[0].battery_left, 82);
  for (int i = 0; i < 4; ++i) sim.step(hover);
  EXPECT_FALSE(sim.uavs()[0].airborne);
  EXPECT_EQ(sim.uavs()[0].battery_left, 100);  // the swap
  for (int i = 0; i < 9; ++i) sim.step(hover);
  EXPECT_EQ(sim.uavs()[0].away_left, 0);
  EXPECT_EQ(sim.uavs()[0].pos, (Cell{5, 2}));
  EXPECT_EQ(sim.uavs()[0].z, 1);
  EXPECT_EQ(sim.uavs()[0].battery_left, 91);
  const MissionResult r = sim.result();
  EXPECT_EQ(r.uavs[0].swaps, 1);
  ASSERT_EQ(r.uavs[0].sorties.size(), 2u);
  EXPECT_EQ(r.uavs[0].sorties[0].landing, 18);
  EXPECT_EQ(r.uavs[0].sorties[1].takeoff, 22);
  EXPECT_EQ(r.uavs[0].flight_steps, 27);
  EXPECT_THROW(sim.return_for_swap(1), LogicError);
}

TEST(Battery, TheSortieLayerSendsHomeTheUavsAPlannerSendsHome) {
  Strip w;
  Simulator sim(w.hull, w.instance, w.params);
  SortieLayer layer;
  const std::vector<Action> hover = {Action::kHover};
  const std::vector<int> uav0 = {0};
  // On the ground before its first take-off: no UAV there to send home.
  EXPECT_THROW(layer.before_step(sim, uav0), LogicError);
  while (sim.uavs()[0].away_left > 0) sim.step(hover);
  const std::vector<int> unknown = {1};
  EXPECT_THROW(layer.before_step(sim, unknown), LogicError);
  // Full battery, at its start cell: the layer alone would not send it home; its planner does.
  EXPECT_FALSE(sim.return_rule().due(0, sim.uavs()[0]));
  layer.before_step(sim, uav0);
  EXPECT_GT(sim.uavs()[0].away_left, 0);
  EXPECT_EQ(layer.planned_returns(), 1);
  EXPECT_EQ(layer.returns(), 0);
  // Already away: not again.
  EXPECT_THROW(layer.before_step(sim, uav0), LogicError);
}

TEST(Battery, TheReturnRuleIsTheFlightHomeTheReserveAndTheMargin) {
  Strip w;
  Simulator sim(w.hull, w.instance, w.params);
  const ReturnRule rule = sim.return_rule();
  ASSERT_TRUE(rule.limited());
  // From (5, 2) on plane 2: flight 7 and landing 1; on plane 1 a climb more. Reserve 5, margin
  // 2 u_z + 1 = 3.
  EXPECT_EQ(rule.flight_home(0, {5, 2}, 2), 8);
  EXPECT_EQ(rule.battery_needed(0, {5, 2}, 2), 16);
  EXPECT_EQ(rule.battery_needed(0, {5, 2}, 1), 17);
  EXPECT_EQ(sim.view().returns.battery_needed(0, {5, 2}, 2), 16);
  EXPECT_FALSE(ReturnRule{}.limited());
}

TEST(Battery, TheSortieLayerSendsAUavHomeWithTheReserveLeft) {
  Strip w;
  Simulator sim(w.hull, w.instance, w.params);
  SortieLayer layer;
  const std::vector<Action> east = {Action::kEast};
  const std::vector<Action> hover = {Action::kHover};
  while (sim.time() < 300) {
    layer.before_step(sim);
    const UavState u = sim.uavs()[0];
    // Towards the far end of the hull, then hovering there.
    sim.step(u.pos.x < 19 ? east : hover);
  }
  const MissionResult r = sim.result();
  EXPECT_EQ(r.battery_crashes, 0);
  EXPECT_GE(layer.returns(), 2);
  EXPECT_EQ(r.uavs[0].swaps, layer.returns());
  EXPECT_GE(r.uavs[0].min_battery, 5);
  for (const auto& s : r.uavs[0].sorties) {
    if (s.landing >= 0) {
      EXPECT_LE(s.landing - s.takeoff, 95);
    }
  }
}

TEST(Battery, StepRulesCountTheBattery) {
  UavState before;
  before.pos = {3, 3};
  before.battery_left = 10;
  UavState after = before;
  after.battery_left = 9;
  EXPECT_FALSE(step_violation(before, after, 1));
  after.battery_left = 10;
  EXPECT_TRUE(step_violation(before, after, 1));  // flew without using the battery
  before.battery_left = 0;
  after.battery_left = -1;
  EXPECT_TRUE(step_violation(before, after, 1));  // flew on empty
  after = before;
  after.failed = true;
  EXPECT_FALSE(step_violation(before, after, 1));  // the crash
  before = UavState{};
  before.pos = {3, 3};
  before.battery_left = 10;
  after = before;
  after.airborne = false;
  after.battery_left = 9;
  EXPECT_TRUE(step_violation(before, after, 1));  // landed on the hull
  after.away_left = 3;
  EXPECT_FALSE(step_violation(before, after, 1));  // landed at its site
}

TEST(Battery, BadValuesAreRefusedNamingTheOption) {
  Strip w;
  auto refused = [&](world::MissionParams p, const std::string& name) {
    try {
      world::validate(p, w.hull);
    } catch (const ParameterError& e) {
      EXPECT_EQ(e.name(), name) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted, expected a refusal of " << name;
  };
  auto p = w.params;
  p.endurance_s = std::numeric_limits<double>::quiet_NaN();
  refused(p, "endurance");
  p.endurance_s = -5;
  refused(p, "endurance");
  p.endurance_s = 100;
  p.reserve_s = 100;
  refused(p, "reserve");
  p.reserve_s = std::numeric_limits<double>::infinity();
  refused(p, "reserve");
  p.reserve_s = 5;
  p.swap_time_s = -1;
  refused(p, "swap-time");
  p = w.params;
  p.launch_sites.clear();
  refused(p, "endurance");
  p = w.params;
  p.endurance_s.reset();
  refused(p, "reserve");
}

TEST(Battery, AnEnduranceTooShortForTheFarthestCellIsRefused) {
  Strip w;
  w.params.endurance_s = 40;
  w.params.reserve_s = 2;
  // Farthest hull cell from (0, 0): (19, 3), 22 steps; both ways with take-off 1 and a plane
  // change 1: 48, plus the reserve 2 and the margin 3 + 1.
  try {
    Simulator sim(w.hull, w.instance, w.params);
    ADD_FAILURE() << "accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.name(), "endurance");
    EXPECT_EQ(e.problem(),
              "40 s cannot reach the farthest hull cell (19, 3) from launch site (0, 0) and come "
              "back: that needs at least 54 s (the flight both ways down to plane 1, a reserve of "
              "2 s and a margin of 4 s)");
  }
  w.params.endurance_s = 54;
  EXPECT_NO_THROW(Simulator(w.hull, w.instance, w.params));
}

}  // namespace
}  // namespace hullinspect::sim
