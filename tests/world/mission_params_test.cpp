#include "hullinspect/world/mission_params.hpp"

#include <gtest/gtest.h>

#include "hullinspect/core/errors.hpp"
#include "support/printers.hpp"

namespace hullinspect::world {
namespace {

TEST(MissionParams, PlaneChangeStepsMatchThePaper) {
  MissionParams p;
  p.s1 = 5;
  for (auto [s2, uz] : {std::pair{7, 1}, {9, 2}, {11, 3}}) {
    p.s2 = s2;
    EXPECT_NEAR(p.delta_zeta_cells(), uz, 1e-9);
    EXPECT_EQ(p.plane_change_steps(), uz) << "s2 = " << s2;
  }
  p.s2 = 9;
  p.theta_deg = 120;  // wider lens: Δζ = 4 / (2·tan 60°) = 1.15 → 2 steps
  EXPECT_EQ(p.plane_change_steps(), 2);
  p.plane_speed_cells = 2;
  EXPECT_EQ(p.plane_change_steps(), 1);
}

TEST(MissionParams, HalfSideIsTheFootprintsChebyshevRadius) {
  EXPECT_EQ(footprint_half(1), 0);
  EXPECT_EQ(footprint_half(5), 2);
  EXPECT_EQ(footprint_half(7), 3);
  MissionParams p;
  p.s1 = 3;
  p.s2 = 9;
  EXPECT_EQ(p.half_side(1), 1);
  EXPECT_EQ(p.half_side(2), 4);
  // A footprint of side s holds the cells within h of its centre: 2h + 1 = s.
  for (int z : {1, 2}) EXPECT_EQ(2 * p.half_side(z) + 1, p.footprint(z));
}

TEST(MissionParams, DefaultStartsAreSpreadAndSnapped) {
  MissionParams p;
  p.uavs = 4;
  const auto starts = start_cells(p, default_hull());
  ASSERT_EQ(starts.size(), 4u);
  EXPECT_EQ(starts[0], (grid::Cell{28, 15}));   // floor(0.5·230/4) = 28
  EXPECT_EQ(starts[3], (grid::Cell{201, 15}));  // floor(3.5·230/4) = 201
  p.uavs = 1;
  p.starts = {{0, 0}};  // not hull: snapped to the nearest hull cell
  const auto snapped = start_cells(p, default_hull());
  EXPECT_TRUE(default_hull().is_hull(snapped[0]));
  EXPECT_EQ(grid::manhattan(snapped[0], {0, 0}), 14);  // several tie; lowest y wins
  EXPECT_EQ(snapped[0], (grid::Cell{3, 11}));
}

std::string message(const MissionParams& p) {
  try {
    validate(p, default_hull());
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MissionParams, ValidationNamesFieldAndRange) {
  MissionParams p;
  EXPECT_EQ(message(p), "no error");
  auto with = [](auto f) {
    MissionParams q;
    f(q);
    return message(q);
  };
  EXPECT_EQ(with([](auto& q) { q.uavs = 0; }), "uavs: must be at least 1 (got 0)");
  EXPECT_EQ(with([](auto& q) { q.uavs = 7000; }),
            "uavs: must be at most the 6361 hull cells (got 7000)");
  EXPECT_EQ(with([](auto& q) { q.s1 = 4; }), "s1: must be a positive odd integer (got 4)");
  EXPECT_EQ(with([](auto& q) { q.s2 = 8; }),
            "s2: must be an odd integer greater than s1 = 5 (got 8)");
  EXPECT_EQ(with([](auto& q) { q.s2 = 5; }),
            "s2: must be an odd integer greater than s1 = 5 (got 5)");
  EXPECT_EQ(with([](auto& q) { q.theta_deg = 180; }),
            "theta: must be in (0, 180) degrees, exclusive (got 180)");
  EXPECT_EQ(with([](auto& q) { q.theta_deg = 0; }),
            "theta: must be in (0, 180) degrees, exclusive (got 0)");
  EXPECT_EQ(with([](auto& q) { q.start_z = 3; }), "start_z: must be 1 or 2 (got 3)");
  EXPECT_EQ(with([](auto& q) { q.time_limit = 0; }), "time_limit: must be at least 1 step (got 0)");
  EXPECT_EQ(with([](auto& q) { q.starts = {{1, 1}}; }), "starts: gives 1 start cell for 4 UAVs");
  EXPECT_EQ(with([](auto& q) {
              q.uavs = 1;
              q.starts = {{300, 1}};
            }),
            "starts: start cell (300, 1) is outside the 230 × 30 grid");
}

}  // namespace
}  // namespace hullinspect::world
