// Neighbour flights in the simulator (docs/model.md "Neighbour flights"): on an unrolled hull a
// move to a neighbour whose stand-off position is k cells away arrives at once and keeps the UAV
// in transit, sensing nothing, for k − 1 more steps; on any other hull every move is one step.
#include <gtest/gtest.h>

#include "hullinspect/sim/simulator.hpp"
#include "hullinspect/sim/uav_rules.hpp"
#include "hullinspect/world/mesh_hull.hpp"
#include "support/mesh_fixtures.hpp"

namespace hullinspect::sim {
namespace {

world::HullMask wigley(world::HullSide side) {
  world::MeshImportOptions o;
  o.side = side;
  o.cell_size = 1.0;
  return world::import_mesh_file(testing::wigley_stl(testing::WigleyHull{}), o).hull;
}

struct Mission {
  world::HullMask hull;
  world::Instance instance;
  world::MissionParams params;
  explicit Mission(world::HullMask h) : hull(std::move(h)) {
    instance.truth = grid::Grid<std::int8_t>(hull.width(), hull.height(), -1);
    for (int i : hull.cells()) instance.truth[i] = 0;
    instance.prior = instance.truth;
    params.uavs = 1;
    params.cell_size_m = hull.geometry()->cell_size;
  }
};

TEST(NeighbourFlights, ALongFlightKeepsTheUavInTransitForItsExtraSteps) {
  Mission m(wigley(world::HullSide::both));
  // The longest eastward flight on plane 2 between two hull cells (around the bow's stem).
  const grid::FlightSteps table = Simulator(m.hull, m.instance, m.params).flight_steps();
  ASSERT_FALSE(table.empty());
  grid::Cell from{-1, -1};
  int longest = 1;
  for (int i : m.hull.cells()) {
    const grid::Cell c = m.hull.mask().cell(i);
    const grid::Cell east{c.x + 1, c.y};
    if (!m.hull.mask().contains(east) || !m.hull.is_hull(east)) continue;
    if (table.between(c, east, 2) > longest) {
      longest = table.between(c, east, 2);
      from = c;
    }
  }
  ASSERT_GE(longest, 3) << "no long flight on the unrolled Wigley hull: the test proves nothing";
  m.params.starts = {from};
  Simulator sim(m.hull, m.instance, m.params);
  const long long seen_before = sim.result().observations;
  sim.step(std::vector<Action>{Action::kEast});
  const UavState after = sim.uavs()[0];
  EXPECT_EQ(after.pos, (grid::Cell{from.x + 1, from.y}));
  EXPECT_EQ(after.flight_left, longest - 1);
  EXPECT_TRUE(after.in_transit());
  EXPECT_EQ(sim.result().observations, seen_before) << "sensed while still flying";
  // Its actions are ignored until the flight's steps are flown; then it senses again.
  for (int s = 1; s < longest; ++s) {
    EXPECT_EQ(sim.result().observations, seen_before);
    sim.step(std::vector<Action>{Action::kEast});
    EXPECT_EQ(sim.uavs()[0].pos, after.pos);
  }
  EXPECT_EQ(sim.uavs()[0].flight_left, 0);
  EXPECT_GT(sim.result().observations, seen_before);
  const UavCounters count = sim.result().uavs[0];
  EXPECT_EQ(count.moves, 1);
  EXPECT_EQ(count.steps_z2, longest);
  // The motion rules accept exactly that flight count.
  UavState start;
  start.pos = from;
  EXPECT_EQ(step_violation(start, after, 1, table), std::nullopt);
  UavState short_flight = after;
  short_flight.flight_left = longest - 2;
  EXPECT_NE(step_violation(start, short_flight, 1, table), std::nullopt);
  UavState early = after;
  early.flight_left = longest - 2;
  early.pos.x += 1;
  EXPECT_NE(step_violation(after, early, 1, table), std::nullopt) << "moved mid-flight";
}

TEST(NeighbourFlights, OneSideHullsHaveNoTable) {
  Mission m(wigley(world::HullSide::starboard));
  EXPECT_TRUE(Simulator(m.hull, m.instance, m.params).flight_steps().empty());
}

}  // namespace
}  // namespace hullinspect::sim
