// Separation at a shared launch site (docs/model.md, "Take-offs and landings under separation"):
// UAVs on the ground do not count, and the deconfliction layer sequences the take-offs.

#include <gtest/gtest.h>

#include "hullinspect/sim/deconfliction.hpp"
#include "hullinspect/sim/simulator.hpp"
#include "support/strip_world.hpp"

namespace hullinspect::sim {
namespace {

using grid::Cell;

// Two UAVs on the strip sharing the site (0, 0), starting at (12, 2) and (5, 2): the first to
// take off flies past the second's start cell before the second takes off.
testing::StripWorld two_on_one_site(int separation) {
  testing::StripWorld w;
  w.params.uavs = 2;
  w.params.starts = {{12, 2}, {5, 2}};
  w.params.launch_sites = {{0, 0}};
  w.params.separation = separation;
  return w;
}

TEST(LaunchSeparation, UavsOnTheGroundDoNotCount) {
  const auto w = two_on_one_site(3);
  Simulator sim(w.hull, w.instance, w.params);
  // Both on the ground at one site: nothing measured.
  EXPECT_EQ(sim.separation_conflicts(), 0);
  EXPECT_FALSE(sim.min_separation().has_value());
  // UAV 1 waits on the ground while UAV 0 takes off: still nothing, one UAV airborne.
  const std::vector<Action> hover(2, Action::kHover);
  const std::vector<std::uint8_t> go_and_wait = {Simulator::kGo, Simulator::kHold};
  sim.step(hover, go_and_wait);
  EXPECT_TRUE(sim.uavs()[0].airborne);
  EXPECT_FALSE(sim.uavs()[1].airborne);
  EXPECT_EQ(sim.separation_conflicts(), 0);
  EXPECT_FALSE(sim.min_separation().has_value());
  // UAV 1 takes off while UAV 0 is at most a cell from the site, without the layer: a conflict.
  sim.step(hover);
  EXPECT_TRUE(sim.uavs()[1].airborne);
  EXPECT_LE(grid::chebyshev(sim.uavs()[0].pos, sim.uavs()[1].pos), 1);
  EXPECT_EQ(sim.separation_conflicts(), 1);
}

TEST(LaunchSeparation, TheLayerSequencesTakeOffsAtASharedSite) {
  for (int d = 1; d <= 3; ++d) {
    SCOPED_TRACE(d);
    const auto w = two_on_one_site(d);
    Simulator sim(w.hull, w.instance, w.params);
    Deconfliction layer(d, 2, 20, 5, nullptr);
    std::vector<Action> actions(2, Action::kHover);
    // Where each UAV is when its flight out ends (a UAV already at work may side-step later).
    Cell arrived[2] = {{-1, -1}, {-1, -1}};
    for (int t = 0; t < 60 && (arrived[0].x < 0 || arrived[1].x < 0); ++t) {
      std::fill(actions.begin(), actions.end(), Action::kHover);
      layer.adjust(sim, actions);
      sim.step(actions, layer.away_orders());
      for (int k = 0; k < 2; ++k) {
        if (arrived[k].x < 0 && sim.uavs()[k].away_left == 0) arrived[k] = sim.uavs()[k].pos;
      }
    }
    EXPECT_EQ(arrived[0], (Cell{12, 2}));
    EXPECT_EQ(arrived[1], (Cell{5, 2}));
    EXPECT_EQ(sim.separation_conflicts(), 0);
    const auto r = sim.result();
    ASSERT_EQ(r.uavs[0].sorties.size(), 1U);
    ASSERT_EQ(r.uavs[1].sorties.size(), 1U);
    // UAV 1 took off only once UAV 0 had flown at least D cells from the site.
    EXPECT_GE(r.uavs[1].sorties[0].takeoff - r.uavs[0].sorties[0].takeoff, d);
  }
}

}  // namespace
}  // namespace hullinspect::sim
