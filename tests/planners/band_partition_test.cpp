// Sweep-Inspect's band partition (planners/band_partition.hpp): the band grid of runs of columns,
// exact pieces on small hulls, every cut at the row boundary nearest its share (against brute
// force over every boundary), 4-connected pieces or an error, and every cell of every piece seen
// by its UAV's sweep on the shared band grid; the re-split at a failure in runs of the same order.
#include "hullinspect/planners/band_partition.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/band_sweep.hpp"
#include "hullinspect/world/hull.hpp"
#include "sweep_coverage.hpp"

namespace hullinspect::planners {
namespace {

/// A hull from rows of text, top row first ('#' hull, '.' not).
world::HullMask hull_from(const std::vector<std::string>& rows) {
  const int height = static_cast<int>(rows.size());
  const int width = static_cast<int>(rows[0].size());
  grid::Grid<std::uint8_t> mask(width, height, 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x)
      mask(x, y) =
          rows[static_cast<std::size_t>(height - 1 - y)][static_cast<std::size_t>(x)] == '#';
  }
  return world::HullMask(std::move(mask), "test");
}

/// The owner of every cell as rows of text, top row first (digits, '.' not hull).
std::vector<std::string> owners(const partition::Partition& p) {
  std::vector<std::string> rows;
  for (int y = p.owner.height() - 1; y >= 0; --y) {
    std::string row;
    for (int x = 0; x < p.owner.width(); ++x)
      row += p.owner(x, y) < 0 ? '.' : static_cast<char>('0' + p.owner(x, y));
    rows.push_back(row);
  }
  return rows;
}

TEST(BandPartition, BandStartsFollowRunsOfOneWidth) {
  const std::vector<int> widths{3, 3, 3, 3, 3, 2, 2, 2, 2, 2, 3, 3};
  EXPECT_EQ(column_band_starts(widths), (std::vector<int>{0, 0, 0, 3, 3, 5, 5, 7, 7, 9, 10, 10}));
}

// A 12 × 6 rectangle in bands of 3: band 0 up, band 1 down, ...; every row costs 1.
TEST(BandPartition, ExactPiecesOnARectangle) {
  const world::HullMask hull = hull_from(std::vector<std::string>(6, std::string(12, '#')));
  const std::vector<int> band_start = column_band_starts(std::vector<int>(12, 3));
  // Two UAVs: 24 rows, two bands each.
  const std::vector<grid::Cell> two{{1, 1}, {10, 1}};
  const auto halves = band_order_partition(hull, {}, band_start, two, 1.0, 0.0);
  EXPECT_EQ(owners(halves), std::vector<std::string>(6, "000000111111"));
  EXPECT_EQ(halves.region_weight, (std::vector<double>{12.0, 12.0}));
  // Three: 8 rows each; band 1 is flown down, so its top two rows end the first piece, band 2's
  // top two rows begin the last. The pieces go to the UAVs in the order of their starts' x.
  const std::vector<grid::Cell> three{{11, 0}, {0, 0}, {6, 0}};
  const auto thirds = band_order_partition(hull, {}, band_start, three, 1.0, 0.0);
  EXPECT_EQ(owners(thirds),
            (std::vector<std::string>{"111111000000", "111111000000", "111222222000",
                                      "111222222000", "111222222000", "111222222000"}));
  // A band's flight to it counts once: with band_cost 6 each band weighs 12, so two UAVs still
  // split between bands 1 and 2.
  const auto costed = band_order_partition(hull, {}, band_start, two, 1.0, 6.0);
  EXPECT_EQ(owners(costed), std::vector<std::string>(6, "000000111111"));
}

// An offset (work a UAV has besides its piece) shortens its piece by half of it against the
// other's: on the 12 × 6 rectangle (24 rows of 1), offsets {4, 0} make the common share (24 + 4) /
// 2 = 14, so UAV 0 gets 10 rows (band 0 and band 1's top four) and UAV 1 14. BandPieces cuts as
// band_order_partition, and moving a cut moves exactly the rows between.
TEST(BandPartition, OffsetsShortenAPieceAndCutsMoveRows) {
  const world::HullMask hull = hull_from(std::vector<std::string>(6, std::string(12, '#')));
  const std::vector<int> band_start = column_band_starts(std::vector<int>(12, 3));
  const std::vector<grid::Cell> two{{1, 1}, {10, 1}};
  const std::vector<double> offset{4.0, 0.0};
  const auto p = band_order_partition(hull, {}, band_start, two, 1.0, 0.0, offset);
  EXPECT_EQ(owners(p), (std::vector<std::string>{"000000111111", "000000111111", "000000111111",
                                                 "000000111111", "000111111111", "000111111111"}));
  EXPECT_EQ(p.region_weight, (std::vector<double>{10.0, 14.0}));
  EXPECT_EQ(p.desired_weight, (std::vector<double>{10.0, 14.0}));
  const BandPieces rows(hull, {}, band_start, two, 1.0, 0.0);
  EXPECT_EQ(rows.rows(), 24u);
  EXPECT_EQ(rows.balanced_cuts(offset), (std::vector<std::size_t>{10}));
  EXPECT_EQ(owners(rows.cut(rows.balanced_cuts())), std::vector<std::string>(6, "000000111111"));
  grid::Grid<std::int16_t> owner = rows.cut(std::vector<std::size_t>{10}).owner;
  rows.assign_rows(owner, 10, 12, 0);  // band 1's two bottom rows (flown down: rows 10-11)
  EXPECT_EQ(owner, rows.cut(std::vector<std::size_t>{12}).owner);
  EXPECT_DOUBLE_EQ(rows.work(0, 12), 12.0);
}

// Cells' extra work moves the cut: the left band's rows weigh more, so its UAV gets fewer.
TEST(BandPartition, ExtraWorkMovesTheCut) {
  const world::HullMask hull = hull_from(std::vector<std::string>(4, std::string(6, '#')));
  const std::vector<int> band_start = column_band_starts(std::vector<int>(6, 3));
  grid::Grid<double> extra(6, 4, 0.0);
  for (int y = 0; y < 4; ++y) extra(0, y) = 2.0;  // band 0's rows weigh 3, band 1's 1: total 16
  const std::vector<grid::Cell> two{{0, 0}, {5, 0}};
  const auto p = band_order_partition(hull, extra, band_start, two, 1.0, 0.0);
  // Running sums of band 0: 3, 6, 9 — 9 is nearest 8; the top row and band 1 go to UAV 1.
  EXPECT_EQ(owners(p), (std::vector<std::string>{"111111", "000111", "000111", "000111"}));
}

// On random hulls (columns of random heights from the bottom row), random extras and n: each
// piece is one run of rows of the boustrophedon, each cut at the row boundary whose running sum
// is nearest k/n of the total (a tie: the later one), found by brute force over every boundary;
// the partition is refused exactly when one of those pieces is not 4-connected.
TEST(BandPartition, CutsAreTheNearestRowBoundariesAgainstBruteForce) {
  std::mt19937_64 random(7);
  int refused = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int width = 4 + static_cast<int>(random() % 20);
    const int height = 3 + static_cast<int>(random() % 8);
    const int s = 1 + 2 * static_cast<int>(random() % 3);
    std::vector<std::string> rows(static_cast<std::size_t>(height), std::string(width, '.'));
    // Even trials: heights that step by at most one between neighbours; odd: any heights.
    int h = 1 + static_cast<int>(random() % height);
    for (int x = 0; x < width; ++x) {
      const int step = static_cast<int>(random() % 3) - 1;
      h = trial % 2 == 1 ? 1 + static_cast<int>(random() % height)
                         : std::clamp(h + step, 1, height);
      for (int y = 0; y < h; ++y) rows[static_cast<std::size_t>(height - 1 - y)][x] = '#';
    }
    const world::HullMask hull = hull_from(rows);
    grid::Grid<double> extra(width, height, 0.0);
    for (int i : hull.cells()) extra[i] = static_cast<double>(random() % 4) * 0.5;
    const std::vector<int> band_start = column_band_starts(std::vector<int>(width, s));
    // The boustrophedon's rows and their work, by brute force over the grid.
    std::vector<std::vector<int>> row_cells;
    std::vector<double> row_work;
    for (int x0 = 0; x0 < width; x0 += s) {
      const bool up = (x0 / s) % 2 == 0;
      bool first_of_band = true;
      for (int r = 0; r < height; ++r) {
        const int y = up ? r : height - 1 - r;
        std::vector<int> cells;
        double work = 0;
        for (int x = x0; x < std::min(width, x0 + s); ++x) {
          if (!hull.is_hull(x, y)) continue;
          cells.push_back(y * width + x);
          work += extra(x, y);
        }
        if (cells.empty()) continue;
        work += 1.0 + (first_of_band ? 2.0 : 0.0);
        first_of_band = false;
        row_cells.push_back(cells);
        row_work.push_back(work);
      }
    }
    const int n = 1 + static_cast<int>(random() % std::min<std::size_t>(5, row_cells.size()));
    std::vector<grid::Cell> starts;
    for (int k = 0; k < n; ++k) starts.push_back({k, 0});
    // Expected cuts: greedy over boundaries, each nearest its target, a tie taking the row, at
    // least one row per piece.
    double total = 0;
    for (double w : row_work) total += w;
    std::vector<int> expected_owner(row_cells.size(), -1);
    std::size_t next = 0;
    double running = 0;
    for (int piece = 0; piece < n; ++piece) {
      const double target = total * (piece + 1) / n;
      // Among the boundaries b (rows next .. b−1 to this piece) that leave a row per later piece,
      // the nearest to the target; ties to the later.
      std::size_t best = next + 1;
      double sum = running + row_work[next];
      double best_sum = sum;
      const std::size_t last =
          piece == n - 1 ? row_cells.size() : row_cells.size() - (n - piece - 1);
      for (std::size_t b = next + 2; b <= last; ++b) {
        sum += row_work[b - 1];
        if (piece == n - 1 || std::abs(sum - target) <= std::abs(best_sum - target)) {
          best = b;
          best_sum = sum;
        }
      }
      for (std::size_t r = next; r < best; ++r) expected_owner[r] = piece;
      running = best_sum;
      next = best;
    }
    SCOPED_TRACE(::testing::Message() << "trial " << trial << " width " << width << " height "
                                      << height << " s " << s << " n " << n);
    // Refused exactly when one of those pieces is not 4-connected (flood fill from one cell).
    grid::Grid<int> piece_of(width, height, -1);
    for (std::size_t r = 0; r < row_cells.size(); ++r) {
      for (int i : row_cells[r]) piece_of[i] = expected_owner[r];
    }
    bool connected = true;
    for (int piece = 0; piece < n; ++piece) {
      std::vector<int> stack;
      std::vector<char> reached(static_cast<std::size_t>(width * height), 0);
      int cells = 0;
      for (int i : hull.cells()) {
        if (piece_of[i] != piece) continue;
        if (cells++ == 0) {
          stack.push_back(i);
          reached[static_cast<std::size_t>(i)] = 1;
        }
      }
      int count = 0;
      while (!stack.empty()) {
        const int i = stack.back();
        stack.pop_back();
        ++count;
        for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          const int nx = i % width + dx;
          const int ny = i / width + dy;
          if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          const int j = ny * width + nx;
          if (piece_of[j] == piece && reached[static_cast<std::size_t>(j)] == 0) {
            reached[static_cast<std::size_t>(j)] = 1;
            stack.push_back(j);
          }
        }
      }
      connected = connected && count == cells;
    }
    if (!connected) {
      EXPECT_THROW(band_order_partition(hull, extra, band_start, starts, 1.0, 2.0), Error);
      ++refused;
      continue;
    }
    const auto p = band_order_partition(hull, extra, band_start, starts, 1.0, 2.0);
    for (std::size_t r = 0; r < row_cells.size(); ++r) {
      for (int i : row_cells[r]) ASSERT_EQ(p.owner[i], expected_owner[r]) << "row " << r;
    }
  }
  EXPECT_GT(refused, 0);    // both outcomes are checked
  EXPECT_LT(refused, 100);  // most random hulls are partitioned
}

// A C-shaped hull whose second band is two runs of rows: the piece that would hold its upper and
// lower rows is not 4-connected, and the partition says so.
TEST(BandPartition, RefusesAPieceThatIsNotConnected) {
  const world::HullMask hull =
      hull_from({"######", "######", "###...", "###...", "######", "######"});
  const std::vector<int> band_start = column_band_starts(std::vector<int>(6, 3));
  const std::vector<grid::Cell> two{{0, 0}, {5, 0}};
  // Rows: band 0 has 6, band 1 (flown down) 4; the cut after 5 rows leaves band 0's top row
  // with band 1, whose top and bottom rows are apart.
  EXPECT_THROW(band_order_partition(hull, {}, band_start, two, 1.0, 0.0), Error);
  // Fewer rows than UAVs.
  const world::HullMask tiny = hull_from({"###"});
  const std::vector<grid::Cell> many{{0, 0}, {1, 0}};
  EXPECT_THROW(
      band_order_partition(tiny, {}, column_band_starts(std::vector<int>(3, 3)), many, 1.0, 0.0),
      Error);
}

// BandPieces::columns of any rows [lo, hi) are the first and last column of the cells that
// assign_rows gives for them.
TEST(BandPartition, ColumnsOfRowsAreThoseOfTheirCells) {
  const auto& hull = world::default_hull();
  for (int s : {5, 7, 11}) {
    const std::vector<int> band_start = column_band_starts(std::vector<int>(hull.width(), s));
    const BandPieces rows(hull, {}, band_start, sweep_coverage::spread_starts(hull.width(), 2), s,
                          s);
    std::mt19937 random(static_cast<unsigned>(s));
    std::uniform_int_distribution<std::size_t> row(0, rows.rows() - 1);
    for (int trial = 0; trial < 50; ++trial) {
      std::size_t lo = row(random);
      std::size_t hi = row(random);
      if (lo > hi) std::swap(lo, hi);
      ++hi;
      grid::Grid<std::int16_t> owner(hull.width(), hull.height(), -1);
      rows.assign_rows(owner, lo, hi, 0);
      int first = hull.width();
      int last = -1;
      for (int i : hull.cells()) {
        if (owner[i] != 0) continue;
        first = std::min(first, i % hull.width());
        last = std::max(last, i % hull.width());
      }
      EXPECT_EQ(rows.columns(lo, hi), std::make_pair(first, last))
          << "s " << s << " rows " << lo << "-" << hi;
    }
  }
}

// On the default hull, for s ∈ {5, 7, 9, 11} and n ∈ {2, 4, 8}: the pieces are 4-connected and
// balanced within one row's work, and each UAV's sweep of its piece on the shared band grid sees
// every cell of it (band_sweep with band_start) from no more bands than the piece touches.
TEST(BandPartition, PiecesOfTheDefaultHullAreBalancedAndSweptOnTheGrid) {
  const auto& hull = world::default_hull();
  for (int s : {5, 7, 9, 11}) {
    const std::vector<int> band_start = column_band_starts(std::vector<int>(hull.width(), s));
    for (int n : {2, 4, 8}) {
      const auto starts = sweep_coverage::spread_starts(hull.width(), n);
      const auto p = band_order_partition(hull, {}, band_start, starts, s, s);
      double total = 0;
      for (double w : p.region_weight) total += w;
      for (int k = 0; k < n; ++k) {
        SCOPED_TRACE(::testing::Message() << "s " << s << " n " << n << " uav " << k);
        EXPECT_LE(std::abs(p.region_weight[static_cast<std::size_t>(k)] - total / n), 2.0 * s);
        const auto waypoints = band_sweep(p.owner, k, s, BandAxis::kColumns, true,
                                          starts[static_cast<std::size_t>(k)], band_start);
        // Every waypoint on a band's centre line.
        for (const grid::Cell w : waypoints) {
          const int centre =
              std::min(band_start[static_cast<std::size_t>(w.x)] + (s - 1) / 2, hull.width() - 1);
          EXPECT_EQ(w.x, centre);
        }
        // Every owned cell within the footprint of the flight between consecutive waypoints.
        const int h = (s - 1) / 2;
        for (int i : hull.cells()) {
          if (p.owner[i] != k) continue;
          const grid::Cell c = hull.mask().cell(i);
          bool seen = false;
          for (const grid::Cell w : waypoints)  // a band of one row is flown as one position
            seen = seen || (std::abs(c.x - w.x) <= h && std::abs(c.y - w.y) <= h);
          for (std::size_t j = 0; j + 1 < waypoints.size() && !seen; ++j) {
            const grid::Cell a = waypoints[j];
            const grid::Cell b = waypoints[j + 1];
            if (a.x != b.x) continue;  // a flight between bands
            seen = std::abs(c.x - a.x) <= h && c.y >= std::min(a.y, b.y) - h &&
                   c.y <= std::max(a.y, b.y) + h;
          }
          EXPECT_TRUE(seen) << "cell " << c.x << "," << c.y;
        }
      }
    }
  }
}

}  // namespace
}  // namespace hullinspect::planners

namespace hullinspect::planners {
namespace {

// The re-split at a failure on the band grid: every cell goes to one UAV, each UAV's cells are
// one run of the boustrophedon (in the order the UAVs are given), and a UAV with a load or far
// from its run gets less of it.
TEST(BandPartition, SplitInBandOrderGivesRunsThatEndTogether) {
  const int width = 12;
  const std::vector<int> band_start = column_band_starts(std::vector<int>(width, 3));
  std::vector<int> all;
  for (int y = 0; y < 6; ++y) {
    for (int x = 0; x < width; ++x) all.push_back(y * width + x);
  }
  const auto run_of = [&](std::vector<std::pair<int, grid::Cell>> uavs, std::vector<double> load) {
    std::vector<int> cells = all;
    std::vector<int> owner(all.size(), -1);
    int assigned = 0;
    split_in_band_order(cells, width, band_start, uavs, load, 1.0, 1.0, [&](int k, int i) {
      EXPECT_EQ(owner[static_cast<std::size_t>(i)], -1);
      owner[static_cast<std::size_t>(i)] = k;
      ++assigned;
    });
    EXPECT_EQ(assigned, static_cast<int>(all.size()));
    // Runs in the boustrophedon's order (cells was sorted into it), in the order of `uavs`.
    std::vector<int> sequence;
    for (int i : cells) {
      const int k = owner[static_cast<std::size_t>(i)];
      if (sequence.empty() || sequence.back() != k) sequence.push_back(k);
    }
    std::vector<int> expected;
    for (const auto& [k, pos] : uavs) {
      if (std::count(owner.begin(), owner.end(), k) > 0) expected.push_back(k);
    }
    EXPECT_EQ(sequence, expected);
    std::vector<int> counts;
    for (const auto& [k, pos] : uavs)
      counts.push_back(static_cast<int>(std::count(owner.begin(), owner.end(), k)));
    return counts;
  };
  // Two UAVs at the two ends, no load: two bands each (24 rows and 4 bands begun in all).
  EXPECT_EQ(run_of({{0, {1, 0}}, {1, {10, 0}}}, {0.0, 0.0}), (std::vector<int>{36, 36}));
  // UAV 0 with 6 steps of load gets fewer rows.
  const auto loaded = run_of({{0, {1, 0}}, {1, {10, 0}}}, {6.0, 0.0});
  EXPECT_LT(loaded[0], 36);
  // The order of the runs follows the order given (ids 1 then 0).
  const auto swapped = run_of({{1, {1, 0}}, {0, {10, 0}}}, {0.0, 0.0});
  EXPECT_EQ(swapped, (std::vector<int>{36, 36}));
}

// A run pays the flight across a long stretch swept already: with a band of cells left at the
// stern end (x 0–2) and four at the bow end (x 48–59) of a 60-column grid, the stern UAV takes
// only the stern band. With the gap counted free the stern UAV's run went on into the bow's
// bands (27 of their 72 cells), which it would have reached by a flight across the hull.
TEST(BandPartition, SplitInBandOrderPaysTheFlightAcrossASweptStretch) {
  const int width = 60;
  const std::vector<int> band_start = column_band_starts(std::vector<int>(width, 3));
  std::vector<int> cells;
  for (int y = 0; y < 6; ++y) {
    for (int x = 0; x < width; ++x) {
      if (x <= 2 || x >= 48) cells.push_back(y * width + x);
    }
  }
  const std::vector<std::pair<int, grid::Cell>> uavs = {{0, {1, 0}}, {1, {58, 0}}};
  std::vector<int> owner(static_cast<std::size_t>(width * 6), -1);
  split_in_band_order(cells, width, band_start, uavs, std::vector<double>{0.0, 0.0}, 1.0, 1.0,
                      [&](int k, int i) { owner[static_cast<std::size_t>(i)] = k; });
  for (int i : cells) {
    const int x = i % width;
    EXPECT_EQ(owner[static_cast<std::size_t>(i)], x <= 2 ? 0 : 1)
        << "cell " << x << "," << i / width;
  }
}

}  // namespace
}  // namespace hullinspect::planners
