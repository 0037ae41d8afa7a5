// Neighbour flights in the simulator (docs/model.md "Neighbour flights"): on an unrolled hull a
// move to a neighbour whose stand-off position is k cells away arrives at once and keeps the UAV
// in transit, sensing nothing, for k − 1 more steps; on any other hull every move is one step.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/sim/lower_bound.hpp"
#include "hullinspect/sim/simulator.hpp"
#include "hullinspect/sim/uav_rules.hpp"
#include "hullinspect/world/mesh_hull.hpp"
#include "hullinspect/world/no_fly.hpp"
#include "hullinspect/world/standoff_surface.hpp"
#include "support/mesh_fixtures.hpp"

namespace hullinspect::sim {
namespace {

world::HullMask wigley(world::HullSide side, bool transom = false) {
  world::MeshImportOptions o;
  o.side = side;
  o.cell_size = 1.0;
  o.include_transom = transom;
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

// The Wigley hull unrolled all round (its stern is a point, so --include transom closes the grid
// there): column 0 and column W − 1 meet at the stern.
TEST(NeighbourFlights, AMoveAcrossTheSeamArrivesAtTheOtherEndOfTheRow) {
  Mission m(wigley(world::HullSide::both, /*transom=*/true));
  ASSERT_TRUE(m.hull.geometry()->seam);
  const int w = m.hull.width();
  const grid::FlightSteps table = Simulator(m.hull, m.instance, m.params).flight_steps();
  ASSERT_TRUE(table.has_seam());
  const int y = m.hull.height() - 1;  // the deck's row: the stern's point is a cell's width away
  const int seam = table.between({0, y}, {w - 1, y}, 2);
  // Its length is the distance between the two ends' stand-off positions on plane 2 (ζ2 = 3.5 m:
  // s2 = 7 cells of 1 m, θ = 90°), a few cells across the sharp stern, not the way round the bow.
  const grid::StandoffPoints points = world::standoff_points(*m.hull.geometry());
  const double zeta = grid::standoff_m(m.params.s2, 1.0, m.params.theta_deg);
  const auto at = [&](int x) {
    const auto& p = points.point(x, y);
    const auto& n = points.normal(x, y);
    return std::array<double, 3>{p[0] + zeta * n[0], p[1] + zeta * n[1], p[2] + zeta * n[2]};
  };
  const auto a = at(0), b = at(w - 1);
  EXPECT_EQ(seam, grid::flight_steps_for(std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2])));
  EXPECT_LT(seam, w / 10);
  m.params.starts = {grid::Cell{0, y}};
  Simulator sim(m.hull, m.instance, m.params);
  const UavState before = sim.uavs()[0];
  sim.step(std::vector<Action>{Action::kWest});
  const UavState after = sim.uavs()[0];
  EXPECT_EQ(after.pos, (grid::Cell{w - 1, y}));
  EXPECT_EQ(after.flight_left, seam - 1);
  EXPECT_EQ(step_violation(before, after, 1, table), std::nullopt);
  // And back east across it; a teleport elsewhere is still refused.
  for (int s = 1; s < seam; ++s) sim.step(std::vector<Action>{Action::kHover});
  sim.step(std::vector<Action>{Action::kEast});
  EXPECT_EQ(sim.uavs()[0].pos, (grid::Cell{0, y}));
  UavState jump = before;
  jump.pos = {w - 2, y};
  EXPECT_NE(step_violation(before, jump, 1, table), std::nullopt);
  // The distance service flies the seam: from column 0 to W − 1 is the seam flight, not the way
  // round the bow; and a planner's move there is "west".
  grid::DistanceService service =
      world::make_distance_service(sim.reachability(), sim.flight_steps());
  const int longer = std::max(seam, table.between({0, y}, {w - 1, y}, 1));
  EXPECT_EQ(service.distance({0, y}, {w - 1, y}), longer);
  EXPECT_EQ(service.next_step({0, y}, {w - 1, y}), (grid::Cell{w - 1, y}));
  EXPECT_EQ(move_to_neighbour({0, y}, {w - 1, y}), Action::kWest);
  EXPECT_EQ(move_to_neighbour({w - 1, y}, {0, y}), Action::kEast);
  // Without the link (the same hull, its seam dropped) the way is round the bow.
  world::HullMask open = m.hull;
  world::HullGeometry g = *open.geometry();
  g.seam = false;
  open.attach_geometry(std::move(g));
  Mission o(std::move(open));
  o.params.starts = {grid::Cell{0, y}};
  Simulator unlinked(o.hull, o.instance, o.params);
  grid::DistanceService around =
      world::make_distance_service(unlinked.reachability(), unlinked.flight_steps());
  EXPECT_GE(around.distance({0, y}, {w - 1, y}), w - 1);
}

// Launch-site legs on an unrolled hull fly the same neighbour flights as the mission: the
// outbound leg from a site at the stern on port to a start at the stern on starboard goes round
// the bow at the stand-off lengths of plane 2.
TEST(NeighbourFlights, LaunchLegsFlyTheStandOffLengths) {
  Mission m(wigley(world::HullSide::both));
  const int w = m.hull.width();
  const int y = m.hull.height() - 1;
  m.params.launch_sites = {grid::Cell{0, y}};
  m.params.starts = {grid::Cell{w - 1, y}};
  Simulator sim(m.hull, m.instance, m.params);
  const grid::FlightSteps table = sim.flight_steps();
  ASSERT_FALSE(table.empty());
  grid::DistanceService plane2(sim.reachability().flyable, table.plane[1]);
  const int flight = plane2.distance({w - 1, y}, {0, y});
  ASSERT_GT(flight, w - 1) << "no long flight on the way: the test proves nothing";
  const world::LaunchLegs& legs = sim.launch_legs();
  EXPECT_EQ(legs.flight_home[0][(grid::Cell{w - 1, y})], flight);
  EXPECT_EQ(legs.outbound[0], legs.transfer_steps + legs.takeoff_steps + flight);
  // Its way home holds one position per step, moving only between neighbours.
  const auto path = legs.path_home(0, {w - 1, y});
  EXPECT_EQ(static_cast<int>(path.size()), flight);
  grid::Cell at{w - 1, y};
  for (const grid::Cell c : path) {
    EXPECT_TRUE(c == at || grid::adjacent(at, c, table.plane[1])) << c.x << "," << c.y;
    at = c;
  }
  EXPECT_EQ(at, (grid::Cell{0, y}));
  // The simulator flies it: the UAV reaches its start, airborne, after the outbound leg, every
  // step by the motion rules.
  std::vector<Action> hover{Action::kHover};
  for (int t = 0; t < legs.outbound[0]; ++t) {
    ASSERT_GT(sim.uavs()[0].away_left, 0) << "t = " << t;
    const UavState before = sim.uavs()[0];
    sim.step(hover);
    EXPECT_EQ(step_violation(before, sim.uavs()[0], 1, table), std::nullopt) << "t = " << t;
  }
  EXPECT_EQ(sim.uavs()[0].pos, (grid::Cell{w - 1, y}));
  EXPECT_EQ(sim.uavs()[0].away_left, 0);
  EXPECT_TRUE(sim.uavs()[0].airborne);
  // The lower bound counts the same leg: the hull is not complete before the UAV is out.
  const LowerBound bound = lower_bound(m.hull, m.instance.truth, m.params);
  EXPECT_GT(bound.t_m, legs.outbound[0]);
}

}  // namespace
}  // namespace hullinspect::sim
