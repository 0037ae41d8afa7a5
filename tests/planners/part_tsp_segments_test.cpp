// Segment division of Part-TSP against a direct reading of model.md §5.3 on random local maps, and
// the segment ends with and without trimming.

#include <gtest/gtest.h>

#include <vector>

#include "hullinspect/planners/part_tsp_segments.hpp"
#include "hullinspect/world/random.hpp"

namespace hullinspect::planners::part_tsp {
namespace {

// model.md §5.3, word for word: strip j holds rows [j·s, (j+1)·s); a column is targeted if a cell
// of the strip in that column is in R_k and holds `value`; segments are maximal runs.
std::vector<StripSegment> brute_force(const grid::Grid<std::int16_t>& owner,
                                      const grid::Grid<std::int8_t>& values, int k, int s,
                                      std::int8_t value) {
  std::vector<StripSegment> out;
  const int b = owner.height();
  for (int j = 0; j * s < b; ++j) {
    const int row = std::min(j * s + (s - 1) / 2, b - 1);
    int start = -1;
    for (int x = 0; x <= owner.width(); ++x) {
      bool targeted = false;
      for (int y = j * s; x < owner.width() && y < std::min((j + 1) * s, b); ++y) {
        targeted = targeted || (owner(x, y) == k && values(x, y) == value);
      }
      if (targeted && start < 0) start = x;
      if (!targeted && start >= 0) {
        out.push_back({j, row, start, x - 1});
        start = -1;
      }
    }
  }
  return out;
}

TEST(PartTspSegments, MatchTheSpecOnRandomMaps) {
  world::RandomStream rng(12345, 99);
  for (int trial = 0; trial < 200; ++trial) {
    const int a = 5 + static_cast<int>(rng.below(30));
    const int b = 3 + static_cast<int>(rng.below(20));
    const int n = 1 + static_cast<int>(rng.below(3));
    grid::Grid<std::int16_t> owner(a, b, -1);
    grid::Grid<std::int8_t> prior(a, b, -1);
    for (int i = 0; i < owner.size(); ++i) {
      if (rng.below(10) == 0) continue;  // not hull
      owner[i] = static_cast<std::int16_t>(rng.below(static_cast<std::uint64_t>(n)));
      prior[i] = rng.below(4) == 0 ? 1 : 0;
    }
    LocalMaps maps(owner, prior, true, n, 3, 7);
    // Resolve a random third of the cells through readings of their owner.
    for (int i = 0; i < owner.size(); ++i) {
      if (owner[i] < 0 || rng.below(3) != 0) continue;
      const std::int8_t v = rng.below(2) == 0 ? sim::kClean : sim::kInspected;
      const std::vector<sim::Reading> r = {sim::Reading{i, v, 0}};
      maps.ingest(owner[i], r);
    }
    std::vector<StripSegment> got;
    for (int k = 0; k < n; ++k) {
      for (int z = 1; z <= 2; ++z) {
        for (std::int8_t value : {sim::kUnknown, sim::kCorrosionSeen}) {
          divide_into_segments(maps, k, z, value, got);
          EXPECT_EQ(got, brute_force(owner, maps.values(), k, z == 1 ? 3 : 7, value))
              << "trial " << trial << " uav " << k << " z " << z << " value " << int(value);
          for (const auto& s : got) {
            EXPECT_TRUE(has_targets(maps, k, z, value, s, s.x_left, s.x_right));
            EXPECT_TRUE(has_targets(maps, k, z, value, s, s.x_right, s.x_left));
          }
        }
      }
    }
  }
}

TEST(PartTspSegments, FlightRowsAreAlignedToTheBottomOfTheGrid) {
  // b = 30, s = 7: strips of rows 0–6, 7–13, 14–20, 21–27 and the partial strip 28–29 whose
  // flight row is clipped to the top row.
  const StripLayout layout{7, 30};
  EXPECT_EQ(layout.strips(), 5);
  EXPECT_EQ(layout.flight_row(0), 3);
  EXPECT_EQ(layout.flight_row(3), 24);
  EXPECT_EQ(layout.flight_row(4), 29);
  EXPECT_EQ(layout.last_row(4), 29);
  EXPECT_EQ(layout.strip_of(27), 3);
  EXPECT_EQ(layout.strip_of(28), 4);
}

TEST(PartTspSegments, EndsAreTrimmedByTheHalfWidthAndMeetInTheMiddle) {
  const StripSegment wide{0, 3, 10, 20};
  EXPECT_EQ(segment_ends(wide, 0), std::make_pair(grid::Cell{10, 3}, grid::Cell{20, 3}));
  EXPECT_EQ(segment_ends(wide, 3), std::make_pair(grid::Cell{13, 3}, grid::Cell{17, 3}));
  const StripSegment exact{0, 3, 10, 16};  // 7 wide = one footprint
  EXPECT_EQ(segment_ends(exact, 3), std::make_pair(grid::Cell{13, 3}, grid::Cell{13, 3}));
  const StripSegment narrow{0, 3, 10, 13};
  EXPECT_EQ(segment_ends(narrow, 3), std::make_pair(grid::Cell{11, 3}, grid::Cell{11, 3}));
  // The footprint [c − 3, c + 3] still spans the whole segment.
  const int c = segment_ends(narrow, 3).first.x;
  EXPECT_LE(c - 3, narrow.x_left);
  EXPECT_GE(c + 3, narrow.x_right);
}

}  // namespace
}  // namespace hullinspect::planners::part_tsp
