// Sweep-Inspect's rejoining of a band after an inspection (planners/band_rejoin.hpp) on a 30 × 12
// grid, row band of 3 on the centre line y = 3 left at (5, 3) towards (25, 3): as far along as the
// UAV now is, short of a cell of the band still unobserved behind the rejoining footprint, never
// at a no-fly position, never past the band's end.
#include "hullinspect/planners/band_rejoin.hpp"

#include <gtest/gtest.h>

#include <cstdint>

#include "hullinspect/sim/types.hpp"

namespace hullinspect::planners {
namespace {

struct Fixture {
  grid::Grid<std::int8_t> map{30, 12, sim::kClean};
  grid::Grid<std::uint8_t> seen{30, 12, sim::kSeenAtZ2};
  sim::SensingLog sensed;
  grid::DistanceService open{30, 12};
  sim::PlannerView view() const { return {0, {}, map, seen, sensed}; }
};

constexpr LeftBand kRowBand{{5, 3}, {25, 3}, BandAxis::kRows};

TEST(BandRejoin, AsFarAsTheUavHasComeWhenTheBandIsObserved) {
  Fixture f;
  EXPECT_EQ(band_rejoin_point(kRowBand, {15, 6}, 1, f.view(), f.open), (grid::Cell{15, 3}));
  // Never past the band's end, never behind where it left.
  EXPECT_EQ(band_rejoin_point(kRowBand, {28, 6}, 1, f.view(), f.open), (grid::Cell{25, 3}));
  EXPECT_EQ(band_rejoin_point(kRowBand, {2, 6}, 1, f.view(), f.open), (grid::Cell{5, 3}));
}

TEST(BandRejoin, StopsShortOfAnUnobservedCellOfTheBand) {
  Fixture f;
  // (10, 2) unknown: from (11, 3) the footprint still sees x = 10; from (12, 3) no longer.
  f.map(10, 2) = sim::kUnknown;
  EXPECT_EQ(band_rejoin_point(kRowBand, {15, 6}, 1, f.view(), f.open), (grid::Cell{11, 3}));
  // A cell the prior expects corroded and nobody has seen counts as unobserved too.
  f.map(10, 2) = sim::kCorrosionSeen;
  f.seen(10, 2) = 0;
  EXPECT_EQ(band_rejoin_point(kRowBand, {15, 6}, 1, f.view(), f.open), (grid::Cell{11, 3}));
  // Outside the band (y = 5 for a band of rows 2-4) it does not matter, nor off the hull.
  f.map(10, 2) = sim::kClean;
  f.map(10, 5) = sim::kUnknown;
  f.map(12, 4) = sim::kNotHull;
  EXPECT_EQ(band_rejoin_point(kRowBand, {15, 6}, 1, f.view(), f.open), (grid::Cell{15, 3}));
}

TEST(BandRejoin, NeverAtANoFlyPosition) {
  Fixture f;
  grid::Grid<std::uint8_t> allowed(30, 12, 1);
  allowed(15, 3) = 0;
  const grid::DistanceService flights(allowed);
  EXPECT_EQ(band_rejoin_point(kRowBand, {15, 6}, 1, f.view(), flights), (grid::Cell{14, 3}));
}

TEST(BandRejoin, ColumnBandsFlownBackwards) {
  Fixture f;
  const LeftBand band{{3, 10}, {3, 1}, BandAxis::kColumns};
  EXPECT_EQ(band_rejoin_point(band, {6, 4}, 1, f.view(), f.open), (grid::Cell{3, 4}));
  f.map(2, 7) = sim::kUnknown;  // seen from y = 6 down to 8: rejoin at 6 at the furthest
  EXPECT_EQ(band_rejoin_point(band, {6, 4}, 1, f.view(), f.open), (grid::Cell{3, 6}));
}

TEST(BandRejoin, WhereItLeftWhenTheTargetIsNotOnTheBand) {
  Fixture f;
  const LeftBand approach{{5, 3}, {25, 8}, BandAxis::kRows};
  EXPECT_EQ(band_rejoin_point(approach, {15, 6}, 1, f.view(), f.open), (grid::Cell{5, 3}));
}

}  // namespace
}  // namespace hullinspect::planners
