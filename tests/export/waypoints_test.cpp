// Trajectory compression, the ship frame and the geo-reference (docs/export.md).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/io/geo_reference.hpp"
#include "hullinspect/io/ship_frame.hpp"
#include "hullinspect/io/waypoints.hpp"

namespace hullinspect::io {
namespace {

using A = WaypointAction;

GridState at(int x, int y, int z, bool transit = false, bool active = true) {
  return {{x, y}, z, transit, active};
}

TEST(CompressTrajectory, MergesCollinearMovesKeepsTurnsHoldsAndPlaneChanges) {
  const std::vector<GridState> s = {
      at(0, 0, 2),       at(1, 0, 2), at(2, 0, 2), at(3, 0, 2),  // east ×3: one leg
      at(3, 1, 2),                                               // north: a turn
      at(3, 1, 2),       at(3, 1, 2),                            // hover ×2: one hold
      at(3, 1, 2, true), at(3, 1, 1),                            // plane change over 2 steps
      at(2, 1, 1),       at(1, 1, 1),                            // west ×2
      at(1, 1, 2),                                               // plane change over 1 step
  };
  const std::vector<GridWaypoint> expected = {
      {0, {0, 0}, 2, A::kStart, 0},        {3, {3, 0}, 2, A::kMove, 3},
      {4, {3, 1}, 2, A::kMove, 1},         {6, {3, 1}, 2, A::kHold, 2},
      {8, {3, 1}, 1, A::kPlaneChange, 2},  {10, {1, 1}, 1, A::kMove, 2},
      {11, {1, 1}, 2, A::kPlaneChange, 1},
  };
  EXPECT_EQ(compress_trajectory(s), expected);
}

TEST(CompressTrajectory, ReversalIsAWaypointAndTheLastHoldEndsAtTheLastFrame) {
  const std::vector<GridState> s = {at(2, 2, 1), at(3, 2, 1), at(2, 2, 1), at(2, 2, 1),
                                    at(2, 2, 1)};
  const std::vector<GridWaypoint> expected = {{0, {2, 2}, 1, A::kStart, 0},
                                              {1, {3, 2}, 1, A::kMove, 1},
                                              {2, {2, 2}, 1, A::kMove, 1},
                                              {4, {2, 2}, 1, A::kHold, 2}};
  EXPECT_EQ(compress_trajectory(s), expected);
}

TEST(CompressTrajectory, AFailedUavFliesNoFurther) {
  const std::vector<GridState> s = {at(0, 0, 2), at(1, 0, 2), at(2, 0, 2),
                                    at(2, 0, 2, false, false), at(2, 0, 2, false, false)};
  const std::vector<GridWaypoint> expected = {{0, {0, 0}, 2, A::kStart, 0},
                                              {2, {2, 0}, 2, A::kMove, 2}};
  EXPECT_EQ(compress_trajectory(s), expected);
}

TEST(CompressTrajectory, ALegBreaksWhereTheSurfaceChanges) {
  const std::vector<GridState> s = {at(0, 0, 2), at(1, 0, 2), at(2, 0, 2), at(3, 0, 2)};
  // Cells x >= 2 lie deeper: in metres the step from x = 1 to x = 2 is not along the legs on
  // either side of it, so it is a leg of its own.
  const auto same = [](grid::Cell a, grid::Cell b) { return (a.x >= 2) == (b.x >= 2); };
  const std::vector<GridWaypoint> expected = {{0, {0, 0}, 2, A::kStart, 0},
                                              {1, {1, 0}, 2, A::kMove, 1},
                                              {2, {2, 0}, 2, A::kMove, 1},
                                              {3, {3, 0}, 2, A::kMove, 1}};
  EXPECT_EQ(compress_trajectory(s, same), expected);
}

TEST(WaypointAction, NamesRoundTrip) {
  for (auto a : {A::kStart, A::kMove, A::kPlaneChange, A::kHold}) {
    A back = A::kStart;
    ASSERT_TRUE(parse_waypoint_action(to_string(a), back));
    EXPECT_EQ(back, a);
  }
  A ignored{};
  EXPECT_FALSE(parse_waypoint_action("land", ignored));
}

TEST(ShipFrame, FlatHullPortAndStarboard) {
  ShipFrameSpec spec;  // 0.5 m cells, s1 = 5, s2 = 7, θ = 90°: ζ1 = 1.25 m, ζ2 = 1.75 m
  EXPECT_EQ(spec.side, HullSide::kStarboard);  // as a plain mask
  spec.side = HullSide::kPort;
  ShipFrame port(spec);
  EXPECT_DOUBLE_EQ(port.standoff_m(1), 1.25);
  EXPECT_DOUBLE_EQ(port.standoff_m(2), 1.75);
  auto p = port.pose({3, 4}, 1);
  EXPECT_DOUBLE_EQ(p.x, 1.75);
  EXPECT_DOUBLE_EQ(p.z, 2.25);
  EXPECT_DOUBLE_EQ(p.y, 1.25);
  EXPECT_NEAR(p.yaw, -std::numbers::pi / 2, 1e-12);  // looking toward −y, at the hull
  spec.side = HullSide::kStarboard;
  spec.x0 = 10;
  spec.z0 = -2;
  spec.ys = -3;
  ShipFrame starboard(spec);
  p = starboard.pose({0, 0}, 2);
  EXPECT_DOUBLE_EQ(p.x, 10.25);
  EXPECT_DOUBLE_EQ(p.z, -1.75);
  EXPECT_DOUBLE_EQ(p.y, -4.75);
  EXPECT_NEAR(p.yaw, std::numbers::pi / 2, 1e-12);
  EXPECT_EQ(starboard.cell_at(p.x, p.z), (grid::Cell{0, 0}));
  EXPECT_EQ(starboard.plane_at({0, 0}, p.y, 0.01), 2);
  EXPECT_EQ(starboard.plane_at({0, 0}, -4.25, 0.01), 1);
  EXPECT_EQ(starboard.plane_at({0, 0}, -4.5, 0.01), 0);
}

TEST(ShipFrame, DepthAndNormalFromAMesh) {
  ShipFrameSpec spec;
  spec.side = HullSide::kPort;
  spec.theta_deg = 60;  // ζ = s·cell / (2·tan 30°)
  spec.depth = grid::Grid<double>(2, 1, 0.0);
  spec.depth(1, 0) = 0.4;
  spec.normal = grid::Grid<std::array<double, 3>>(2, 1, {0.0, 1.0, 0.0});
  spec.normal(1, 0) = {std::sqrt(0.5), std::sqrt(0.5), 0.0};
  ShipFrame f(spec);
  const double zeta1 = 5 * 0.5 / (2 * std::tan(std::numbers::pi / 6));
  EXPECT_NEAR(f.pose({0, 0}, 1).y, zeta1, 1e-12);
  EXPECT_NEAR(f.pose({1, 0}, 1).y, zeta1 + 0.4, 1e-12);
  EXPECT_NEAR(f.pose({1, 0}, 1).yaw, -3 * std::numbers::pi / 4, 1e-12);  // along −normal
  EXPECT_FALSE(f.same_surface({0, 0}, {1, 0}));
  EXPECT_TRUE(f.same_surface({1, 0}, {1, 0}));
  EXPECT_EQ(f.plane_at({1, 0}, zeta1 + 0.4, 0.01), 1);
}

TEST(GeoReference, ShipAxesFollowTheHeading) {
  const GeoReference north({53.5, 9.9, 10.0}, 0.0);  // bow to the north: port is west
  auto e = north.to_enu(1, 0, 0);
  EXPECT_NEAR(e.north, 1, 1e-12);
  EXPECT_NEAR(e.east, 0, 1e-12);
  e = north.to_enu(0, 1, 0);
  EXPECT_NEAR(e.east, -1, 1e-12);
  const GeoReference east({53.5, 9.9, 10.0}, 90.0);  // bow to the east: port is north
  e = east.to_enu(1, 2, 3);
  EXPECT_NEAR(e.east, 1, 1e-12);
  EXPECT_NEAR(e.north, 2, 1e-12);
  EXPECT_NEAR(e.up, 3, 1e-12);
  // 100 m toward the bow is 100 m north: about 0.0009 degrees of latitude at 53.5° N.
  const auto g = north.to_wgs84(100, 0, 0);
  EXPECT_NEAR(g.lon, 9.9, 1e-9);
  EXPECT_NEAR((g.lat - 53.5) * 111'300, 100, 0.5);
  // Yaw: looking at the bow is the heading; looking to port is 90° left of it.
  EXPECT_NEAR(east.compass_deg(0), 90, 1e-9);
  EXPECT_NEAR(east.compass_deg(std::numbers::pi / 2), 0, 1e-9);
  EXPECT_NEAR(north.compass_deg(std::numbers::pi / 2), 270, 1e-9);
  EXPECT_NEAR(east.ship_yaw(0), std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(east.enu_rotation(), 0, 1e-12);
}

TEST(GeoReference, RoundTripWithinAMillimetre) {
  const GeoReference ref({-33.86, 151.21, 25.0}, 237.5);
  double worst = 0;
  for (double x = -50; x <= 150; x += 12.5) {
    for (double y : {-9.0, -1.25, 0.0, 1.75, 8.0}) {
      for (double z : {-12.0, 0.25, 15.0}) {
        const auto g = ref.to_wgs84(x, y, z);
        double bx = 0, by = 0, bz = 0;
        ref.from_wgs84(g, bx, by, bz);
        worst = std::max({worst, std::abs(bx - x), std::abs(by - y), std::abs(bz - z)});
      }
    }
  }
  EXPECT_LT(worst, 1e-3);
  EXPECT_LT(worst, 1e-6);  // GeographicLib's exact transformation: far below a millimetre
}

TEST(GeoReference, RejectsBadOrigins) {
  EXPECT_THROW(GeoReference({91, 0, 0}, 0), ParameterError);
  EXPECT_THROW(GeoReference({0, 181, 0}, 0), ParameterError);
  EXPECT_THROW(GeoReference({0, 0, NAN}, 0), ParameterError);
  EXPECT_THROW(GeoReference({0, 0, 0}, INFINITY), ParameterError);
  const auto o = parse_geo_origin("53.5,-9.25,12");
  EXPECT_DOUBLE_EQ(o.lat, 53.5);
  EXPECT_DOUBLE_EQ(o.lon, -9.25);
  EXPECT_DOUBLE_EQ(o.alt, 12);
  for (const char* bad : {"", "1,2", "1,2,3,4", "a,2,3", "1, 2,3", "1,,3", "1,2,inf"}) {
    EXPECT_THROW(parse_geo_origin(bad), ParameterError) << bad;
  }
}

}  // namespace
}  // namespace hullinspect::io
