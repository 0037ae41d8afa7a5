// The lower bound on a grid that closes on itself (docs/model.md §11): a cell across the seam is
// as near as the shorter way round, so the reach argument measures columns that way.

#include <gtest/gtest.h>

#include <string>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/sim/lower_bound.hpp"
#include "support/seam_hull.hpp"

namespace hullinspect::sim {
namespace {

world::HullMask ring(bool seam) {
  std::string rows;
  for (int y = 0; y < 4; ++y) rows += std::string(40, 'X') + "\n";
  world::HullMask hull = testing::seam_cylinder_hull(rows);
  if (!seam) {
    world::HullGeometry g = *hull.geometry();
    g.seam = false;
    hull.attach_geometry(std::move(g));
  }
  return hull;
}

TEST(SeamBound, TheReachArgumentGoesTheShorterWayRound) {
  world::MissionParams params;
  params.uavs = 1;
  params.cell_size_m = 1.0;
  const std::vector<grid::Cell> start = {{0, 1}};
  const grid::Grid<std::int8_t> clean(40, 4, 0);
  // The farthest cell from column 0 is column 20 round the ring (20 columns, s2 = 7 sees 3 of
  // them), column 39 on the grid that does not close.
  EXPECT_EQ(lower_bound(ring(true), clean, params, start).reach_t_m, 20 - 3);
  EXPECT_EQ(lower_bound(ring(false), clean, params, start).reach_t_m, 39 - 3);
}

TEST(SeamBound, NoPlannersMissionBeatsTheBound) {
  const world::HullMask hull = ring(true);
  for (const auto& info : planners::planner_registry()) {
    SCOPED_TRACE(info.name);
    planners::MissionSpec spec;
    spec.algorithm = info.name;
    spec.params.uavs = 1;
    spec.params.cell_size_m = 1.0;
    spec.params.starts = {{0, 1}};
    spec.seed = 2;
    const MissionResult r = planners::run_mission(spec, hull);
    ASSERT_TRUE(r.complete);
    EXPECT_GE(*r.t_m, r.bound_t_m);
    EXPECT_GE(r.bound_t_m, 20 - 3);
  }
}

}  // namespace
}  // namespace hullinspect::sim
