// The incremental state behind Coop-Frontier: the Manhattan distance transform against brute force,
// the lazily refreshed source fields and their updates after removals, the floor of d_HP over a
// changing set, the indexed cell set and the frontier set against its definition.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "hullinspect/grid/distance.hpp"
#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/planners/coop_frontier_cell_set.hpp"
#include "hullinspect/planners/coop_frontier_distance_floor.hpp"
#include "hullinspect/planners/coop_frontier_fields.hpp"
#include "hullinspect/planners/coop_frontier_frontiers.hpp"
#include "hullinspect/sim/types.hpp"
#include "hullinspect/world/random.hpp"

namespace hullinspect::planners {
namespace {

int brute_force_distance(const grid::Grid<std::uint8_t>& sources, int index) {
  const grid::Cell c = sources.cell(index);
  int best = grid::kUnreachable;
  for (int j = 0; j < sources.size(); ++j) {
    if (sources[j]) best = std::min(best, grid::manhattan(c, sources.cell(j)));
  }
  return best;
}

TEST(ManhattanDistanceTransform, MatchesBruteForceOnRandomSourceSets) {
  world::RandomStream rng(42, 0);
  grid::Grid<int> out;
  for (int trial = 0; trial < 60; ++trial) {
    const int w = 1 + static_cast<int>(rng.below(25));
    const int h = 1 + static_cast<int>(rng.below(13));
    const double density = trial % 3 == 0 ? 0.0 : (trial % 3 == 1 ? 0.02 : 0.3);
    grid::Grid<std::uint8_t> sources(w, h, 0);
    for (int i = 0; i < sources.size(); ++i) sources[i] = rng.bernoulli(density) ? 1 : 0;
    manhattan_distance_transform(sources, out);
    for (int i = 0; i < sources.size(); ++i) {
      ASSERT_EQ(out[i], brute_force_distance(sources, i))
          << "trial " << trial << " " << w << "x" << h << " cell " << i;
    }
  }
}

TEST(SourceDistanceField, WithNoFlyPositionsRecomputesOnlyWhenReadAfterAChange) {
  // One no-fly position, (9, 0), out of every shortest path below: the field comes from searches.
  grid::Grid<std::uint8_t> allowed(10, 4, 1);
  allowed(9, 0) = 0;
  grid::DistanceService service(allowed);
  SourceDistanceField f;
  f.reset(10, 4, &service);
  EXPECT_TRUE(f.empty());
  f.refresh();
  EXPECT_EQ(f.transforms(), 0);  // nothing changed since reset: the field is already "all far"
  EXPECT_EQ(f.distance(5), grid::kUnreachable);

  f.set(3, true);
  f.set(3, true);  // no change
  f.set(30, true);
  EXPECT_TRUE(f.stale());
  f.refresh();
  f.refresh();
  EXPECT_EQ(f.transforms(), 1);
  EXPECT_EQ(f.count(), 2);
  EXPECT_EQ(f.distance(0), 3);   // (0, 0) to (3, 0)
  EXPECT_EQ(f.distance(39), 9);  // (9, 3) to (0, 3) is 9, to (3, 0) is 9
  f.set(3, false);
  f.set(3, false);
  f.refresh();
  EXPECT_EQ(f.transforms(), 2);
  EXPECT_EQ(f.distance(0), 3);  // (0, 0) to (0, 3)
  EXPECT_EQ(f.distance(39), 9);
  f.set(30, false);
  f.refresh();
  EXPECT_TRUE(f.empty());
  EXPECT_EQ(f.distance(0), grid::kUnreachable);
}

// Read on demand (no no-fly positions, a grid above the size limit, here 0), every read must equal
// the definition after any sequence of additions and removals, on grids taller than one 64-row
// word; small grids keep the transform.
TEST(SourceDistanceField, ManhattanReadsMatchBruteForceThroughAddsAndRemovals) {
  world::RandomStream rng(7, 0);
  for (int trial = 0; trial < 40; ++trial) {
    const int w = 1 + static_cast<int>(rng.below(30));
    const int h = 1 + static_cast<int>(rng.below(trial % 2 == 0 ? 12 : 150));
    SourceDistanceField f;
    f.reset(w, h, nullptr, 0);  // on demand at every size
    grid::Grid<std::uint8_t> members(w, h, 0);
    for (int step = 0; step < 60; ++step) {
      // Mostly removals after a first filling, as with the prior's cells being seen.
      const int changes = 1 + static_cast<int>(rng.below(8));
      for (int c = 0; c < changes; ++c) {
        const int i = static_cast<int>(rng.below(static_cast<std::uint64_t>(w * h)));
        const bool member = step < 5 ? true : rng.below(5) == 0;
        members[i] = member ? 1 : 0;
        f.set(i, member);
      }
      f.refresh();
      EXPECT_EQ(f.transforms(), 0);
      for (int probe = 0; probe < 20; ++probe) {
        const int i = static_cast<int>(rng.below(static_cast<std::uint64_t>(w * h)));
        ASSERT_EQ(f.distance(i), brute_force_distance(members, i))
            << "trial " << trial << " " << w << "x" << h << " step " << step << " cell " << i;
      }
    }
  }
}

// Held as a Manhattan field, removals update only the cells whose nearest members left: every
// cell must equal the definition after every update, and an addition must bring back the transform.
TEST(SourceDistanceField, RemovalsUpdateTheManhattanFieldExactlyWithoutATransform) {
  world::RandomStream rng(11, 0);
  for (int trial = 0; trial < 40; ++trial) {
    const int w = 1 + static_cast<int>(rng.below(40));
    const int h = 1 + static_cast<int>(rng.below(trial % 2 == 0 ? 6 : 30));
    SourceDistanceField f;
    f.reset(w, h);
    grid::Grid<std::uint8_t> members(w, h, 0);
    const double density = trial % 3 == 0 ? 0.02 : (trial % 3 == 1 ? 0.2 : 0.6);
    for (int i = 0; i < members.size(); ++i) {
      if (!rng.bernoulli(density)) continue;
      members[i] = 1;
      f.set(i, true);
    }
    f.refresh();
    const long long transforms = f.transforms();
    const int first_count = f.count();
    for (int step = 0; step < 30; ++step) {
      // Remove a few members, sometimes a whole block of neighbours (a prior patch seen at once).
      const int changes = 1 + static_cast<int>(rng.below(step % 4 == 0 ? 12 : 3));
      const int x0 = static_cast<int>(rng.below(static_cast<std::uint64_t>(w)));
      const int y0 = static_cast<int>(rng.below(static_cast<std::uint64_t>(h)));
      for (int c = 0; c < changes; ++c) {
        int i = step % 4 == 0 ? std::min(h - 1, y0 + c / 4) * w + std::min(w - 1, x0 + c % 4)
                              : static_cast<int>(rng.below(static_cast<std::uint64_t>(w * h)));
        // Single removals take the next member from a random cell, so that each removes one.
        for (int k = 0; step % 4 != 0 && k < w * h && members[i] == 0; ++k) i = (i + 1) % (w * h);
        members[i] = 0;
        f.set(i, false);
      }
      f.refresh();
      ASSERT_EQ(f.transforms(), transforms) << "trial " << trial << " step " << step;
      for (int i = 0; i < members.size(); ++i) {
        ASSERT_EQ(f.distance(i), brute_force_distance(members, i))
            << "trial " << trial << " " << w << "x" << h << " step " << step << " cell " << i;
      }
    }
    if (f.count() < first_count) {
      EXPECT_GT(f.partial_updates(), 0) << "trial " << trial;
    }
    int back = static_cast<int>(rng.below(static_cast<std::uint64_t>(w * h)));
    while (members[back] != 0) back = (back + 1) % (w * h);  // a cell that is not a member
    members[back] = 1;
    f.set(back, true);
    f.refresh();
    EXPECT_EQ(f.transforms(), transforms + 1);
    for (int i = 0; i < members.size(); ++i) {
      ASSERT_EQ(f.distance(i), brute_force_distance(members, i)) << "after an addition, cell " << i;
    }
  }
}

// The last member's removal leaves every cell unreachable, as the transform of an empty set.
TEST(SourceDistanceField, RemovingEveryMemberLeavesNoDistance) {
  SourceDistanceField f;
  f.reset(7, 5);
  f.set(8, true);
  f.set(30, true);
  f.refresh();
  f.set(8, false);
  f.refresh();
  EXPECT_EQ(f.distance(0), 6);  // (0, 0) to (2, 4)
  f.set(30, false);
  f.refresh();
  EXPECT_EQ(f.transforms(), 1);
  for (int i = 0; i < 35; ++i) EXPECT_EQ(f.distance(i), grid::kUnreachable) << i;
}

TEST(SourceDistanceField, SmallGridsKeepTheTransformLargeOnesReadOnDemand) {
  for (const int side : {50, 400}) {
    SourceDistanceField f;
    f.reset(side, side);
    f.set(3, true);
    f.refresh();
    EXPECT_EQ(f.distance(0), 3);
    EXPECT_EQ(f.transforms(), side * side > SourceDistanceField::kOnDemandCells ? 0 : 1) << side;
  }
}

TEST(IndexedCellSet, InsertEraseAndMembership) {
  IndexedCellSet s;
  s.reset(5, 3);
  s.insert(7);
  s.insert(2);
  s.insert(7);
  s.insert(14);
  EXPECT_EQ(s.size(), 3);
  s.erase(2);
  s.erase(2);
  EXPECT_EQ(s.size(), 2);
  EXPECT_FALSE(s.contains(2));
  EXPECT_TRUE(s.contains(7));
  EXPECT_TRUE(s.contains(14));
  std::set<int> members(s.indices().begin(), s.indices().end());
  EXPECT_EQ(members, (std::set<int>{7, 14}));
  for (std::size_t j = 0; j < s.indices().size(); ++j) {
    EXPECT_EQ(s.cells()[j], (grid::Cell{s.indices()[j] % 5, s.indices()[j] / 5}));
  }
  s.erase(14);
  s.erase(7);
  EXPECT_TRUE(s.empty());
}

std::set<int> frontier_by_definition(const grid::Grid<std::int8_t>& map) {
  std::set<int> f;
  for (int i = 0; i < map.size(); ++i) {
    if (FrontierSet::is_frontier(map, i)) f.insert(i);
  }
  return f;
}

TEST(FrontierSet, DefinitionOnAHandMadeMap) {
  // y = 2:  . 0 0 0
  // y = 1:  0 1 0 0     '.' is not hull (−1), 1 known, 0 unknown
  // y = 0:  0 0 0 0
  grid::Grid<std::int8_t> map(4, 3, sim::kUnknown);
  map(0, 2) = sim::kNotHull;
  map(1, 1) = sim::kClean;
  FrontierSet f;
  f.reset(map);
  // Neighbours of (1, 1): (0, 1), (2, 1), (1, 0), (1, 2); neighbours of the non-hull (0, 2):
  // (1, 2) and (0, 1). Positions off the grid do not count.
  std::set<int> got(f.indices().begin(), f.indices().end());
  EXPECT_EQ(got,
            (std::set<int>{map.index(0, 1), map.index(2, 1), map.index(1, 0), map.index(1, 2)}));
}

TEST(FrontierSet, IncrementalUpdatesMatchTheDefinition) {
  world::RandomStream rng(7, 0);
  for (int trial = 0; trial < 20; ++trial) {
    const int w = 3 + static_cast<int>(rng.below(21));
    const int h = 3 + static_cast<int>(rng.below(9));
    grid::Grid<std::int8_t> map(w, h, sim::kUnknown);
    for (int i = 0; i < map.size(); ++i) {
      if (rng.bernoulli(0.1)) map[i] = sim::kNotHull;
      if (rng.bernoulli(0.05)) map[i] = sim::kCorrosionSeen;
    }
    FrontierSet f;
    f.reset(map);
    std::vector<int> order;
    for (int i = 0; i < map.size(); ++i) {
      if (map[i] == sim::kUnknown) order.push_back(i);
    }
    // Reveal the unknown cells in a random order, in batches like one step's sensing.
    for (std::size_t k = order.size(); k > 1; --k) {
      std::swap(order[k - 1], order[static_cast<std::size_t>(rng.below(k))]);
    }
    std::size_t next = 0;
    while (next < order.size()) {
      const std::size_t batch =
          std::min(order.size() - next, static_cast<std::size_t>(1 + rng.below(6)));
      for (std::size_t b = 0; b < batch; ++b) map[order[next + b]] = sim::kClean;
      for (std::size_t b = 0; b < batch; ++b) f.on_known(order[next + b], map);
      next += batch;
      std::set<int> got(f.indices().begin(), f.indices().end());
      ASSERT_EQ(got, frontier_by_definition(map)) << "trial " << trial << " after " << next;
      for (int i : got) ASSERT_TRUE(f.contains(i));
    }
    EXPECT_TRUE(f.empty());
  }
}

}  // namespace
}  // namespace hullinspect::planners

namespace hullinspect::planners {
namespace {

// The floor equals the least (capped) current distance over the members whenever distances only
// grow, through joins, departures and growth, whatever was read before.
TEST(DistanceFloor, EqualsTheLeastCurrentDistanceOfTheMembers) {
  world::RandomStream rng(5, 0);
  for (int trial = 0; trial < 50; ++trial) {
    const int cells = 1 + static_cast<int>(rng.below(300));
    const int levels = 2 + static_cast<int>(rng.below(20));
    std::vector<int> distance(static_cast<std::size_t>(cells));
    for (int& d : distance) d = static_cast<int>(rng.below(10));
    std::vector<unsigned char> member(static_cast<std::size_t>(cells), 0);
    std::vector<unsigned char> ever(static_cast<std::size_t>(cells), 0);
    DistanceFloor floor;
    floor.reset(cells, levels);
    for (int step = 0; step < 80; ++step) {
      for (int c = static_cast<int>(rng.below(6)); c > 0; --c) {  // joins: each cell once
        const int i = static_cast<int>(rng.below(static_cast<std::uint64_t>(cells)));
        if (ever[static_cast<std::size_t>(i)]) continue;
        ever[static_cast<std::size_t>(i)] = member[static_cast<std::size_t>(i)] = 1;
        floor.add(i);
      }
      for (int c = static_cast<int>(rng.below(3)); c > 0; --c) {  // departures
        member[rng.below(static_cast<std::uint64_t>(cells))] = 0;
      }
      for (int c = static_cast<int>(rng.below(20)); c > 0; --c) {  // distances grow
        int& d = distance[rng.below(static_cast<std::uint64_t>(cells))];
        if (d == grid::kUnreachable) continue;
        d = rng.below(4) == 0 ? grid::kUnreachable : d + 1 + static_cast<int>(rng.below(3));
      }
      int expected = levels - 1;
      for (int i = 0; i < cells; ++i) {
        if (member[static_cast<std::size_t>(i)]) {
          expected = std::min(expected, distance[static_cast<std::size_t>(i)]);
        }
      }
      const int got = floor.lowest([&](int i) { return member[static_cast<std::size_t>(i)] != 0; },
                                   [&](int i) { return distance[static_cast<std::size_t>(i)]; });
      ASSERT_EQ(got, expected) << "trial " << trial << " step " << step;
    }
  }
}

}  // namespace
}  // namespace hullinspect::planners
