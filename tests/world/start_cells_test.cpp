// Default start cells are distinct for every fleet size the CLI accepts (1 … number of hull
// cells), spread over the hull's own extent; derived quantities are refused before they overflow.

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/mission_params.hpp"

namespace hullinspect::world {
namespace {

void expect_distinct_hull_starts(const HullMask& hull, int n) {
  MissionParams p;
  p.uavs = n;
  const auto starts = start_cells(p, hull);
  ASSERT_EQ(starts.size(), static_cast<std::size_t>(n));
  std::set<std::pair<int, int>> seen;
  for (const auto& c : starts) {
    EXPECT_TRUE(hull.is_hull(c)) << n;
    EXPECT_TRUE(seen.insert({c.x, c.y}).second)
        << "n = " << n << ": two UAVs on (" << c.x << ", " << c.y << ")";
  }
  EXPECT_NO_THROW(validate(p, hull)) << n;
}

TEST(StartCells, DistinctForEveryFleetSizeUpTo200OnTheDefaultHull) {
  for (int n = 1; n <= 200; ++n) expect_distinct_hull_starts(default_hull(), n);
}

TEST(StartCells, DistinctWhenEveryHullCellHoldsAUav) {
  for (const char* text : {"X\n", "XX\n", "XXXXXXXX\nXXXXXXXX\nXXXXXXXX\nXXXXXXXX\n",
                           "......\n.XXXX.\n.X..X.\n.XXXX.\n", "X....\nXXXXX\n....X\n",
                           "..X..\n..X..\nXXXXX\n..X..\n..X..\n"}) {
    const HullMask hull = parse_text_mask(text, "small");
    for (int n = 1; n <= hull.cell_count(); ++n) expect_distinct_hull_starts(hull, n);
  }
}

TEST(StartCells, SpreadOverTheHullsOwnExtentNotTheGrids) {
  // A hull in the right half of a wide grid: the single UAV starts mid-hull, not mid-grid.
  const HullMask hull = parse_text_mask("..........XXXXXXXXXX\n..........XXXXXXXXXX\n", "right");
  MissionParams p;
  p.uavs = 1;
  EXPECT_EQ(start_cells(p, hull).front(), (grid::Cell{15, 1}));
  p.uavs = 2;
  const auto two = start_cells(p, hull);
  EXPECT_EQ(two[0], (grid::Cell{12, 1}));
  EXPECT_EQ(two[1], (grid::Cell{17, 1}));
}

std::string refusal(const MissionParams& p) {
  try {
    validate(p, default_hull());
  } catch (const ParameterError& e) {
    return e.name() + ": " + e.problem();
  }
  return "accepted";
}

TEST(StartCells, TinyApertureIsRefusedBeforeItOverflows) {
  MissionParams p;
  p.theta_deg = 1e-300;  // Δζ ≈ 1e302 cells: no int holds its plane change
  EXPECT_EQ(refusal(p),
            "theta: 1e-300° with s1 = 5 and s2 = 7 puts the planes 1.15e+302 cells apart, a plane "
            "change of more than 1000 steps (widen theta)");
  p.theta_deg = 1e-308;
  EXPECT_EQ(refusal(p).rfind("theta: 1e-308° with s1 = 5", 0), 0u);
  EXPECT_GT(p.plane_change_steps(), 1000);  // defined, clamped
}

TEST(StartCells, AHugeFootprintIsBlamedOnS2) {
  MissionParams p;
  p.s2 = 4097;
  EXPECT_EQ(refusal(p),
            "s2: with s1 = 5 and theta = 90° puts the planes 2.05e+03 cells apart, a plane change "
            "of more than 1000 steps (lower s2)");
}

TEST(StartCells, ExplicitStartsOnOneCellAreRefusedUpFront) {
  MissionParams p;
  p.uavs = 2;
  p.starts = {{0, 0}, {3, 11}};  // (0, 0) is not hull and snaps to (3, 11)
  EXPECT_EQ(refusal(p),
            "starts: UAVs 0 and 1 both start on cell (3, 11) (given (0, 0) and (3, 11); cells off "
            "the hull snap to the nearest hull cell); every UAV needs its own start cell");
}

TEST(StartCells, ValidationReturnsTheStartCellsItChecked) {
  MissionParams p;
  p.uavs = 6;
  p.separation = 3;
  EXPECT_EQ(validate(p, default_hull()), start_cells(p, default_hull()));
}

TEST(StartCells, TheStartChecksUseTheCellsTheyAreGiven) {
  // A mission computes its start cells once and hands them to validate_starts(), which checks
  // those cells, not cells of its own.
  const HullMask hull = parse_text_mask("XXXXXX\nXXXXXX\n", "plate");
  MissionParams p;
  p.uavs = 2;
  p.separation = 2;
  validate_without_starts(p, hull);
  EXPECT_NO_THROW(validate_starts(p, hull, std::vector<grid::Cell>{{0, 0}, {5, 1}}));
  try {
    validate_starts(p, hull, std::vector<grid::Cell>{{0, 0}, {1, 1}});
    FAIL() << "expected a separation error";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.name(), "separation");
    EXPECT_EQ(e.problem(),
              "2 cells: UAVs 0 and 1 start 1 cell apart, at (0, 0) and (1, 1) (give --start cells "
              "at least 2 apart, or fewer UAVs)");
  }
}

}  // namespace
}  // namespace hullinspect::world
