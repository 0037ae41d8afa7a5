// TargetSearch (grid/target_search.hpp): the move towards a target from a search that runs only as
// far as the position asked about, with the whole-grid service's answers.
#include "hullinspect/grid/target_search.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "hullinspect/grid/distance_service.hpp"

namespace hullinspect::grid {
namespace {

// A w × h grid with some no-fly positions, flights of 1 … 7 steps and (when `seam`) rows linked
// across the seam, drawn from `rng`.
DistanceService random_service(std::mt19937& rng, int w, int h, bool seam) {
  std::uniform_int_distribution<int> percent(0, 99);
  Grid<std::uint8_t> allowed(w, h, 1);
  EdgeSteps steps{Grid<std::uint8_t>(w, h, 1), Grid<std::uint8_t>(w, h, 1), {}};
  for (int i = 0; i < allowed.size(); ++i) {
    if (percent(rng) < 15) allowed[i] = 0;
    if (percent(rng) < 25) steps.east[i] = static_cast<std::uint8_t>(2 + percent(rng) % 6);
    if (percent(rng) < 25) steps.north[i] = static_cast<std::uint8_t>(2 + percent(rng) % 6);
  }
  if (seam) {
    steps.seam.resize(static_cast<std::size_t>(h));
    for (auto& s : steps.seam)
      s = static_cast<std::uint8_t>(percent(rng) < 25 ? 0 : 1 + percent(rng) % 5);
  }
  return DistanceService(allowed, steps);
}

// Every (from, to) pair, asked in an order that restarts, resumes and reuses the search: the
// answers are the whole-grid service's.
TEST(TargetSearch, AnswersAsTheWholeGridService) {
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE(seed);
    std::mt19937 rng(seed);
    DistanceService reference = random_service(rng, 11, 7, seed > 3);
    DistanceService bound = reference;
    TargetSearch search;
    search.bind(&bound);
    const Grid<std::uint8_t>& allowed = reference.allowed_mask();
    for (int t = 0; t < allowed.size(); ++t) {
      const Cell to = allowed.cell(t);
      // Nearest first (reuses the settled part), then farther (resumes), then near again.
      for (const int pass : {0, 1}) {
        for (int f = 0; f < allowed.size(); ++f) {
          const int i = pass == 0 ? f : allowed.size() - 1 - f;
          const Cell from = allowed.cell(i);
          if (!reference.allowed(from)) continue;
          ASSERT_EQ(search.next_step(from, to), reference.next_step(from, to))
              << "from (" << from.x << ", " << from.y << ") to (" << to.x << ", " << to.y << ")";
        }
      }
    }
  }
}

// Following the search's moves from a position reaches the target in exactly the distance.
TEST(TargetSearch, ItsMovesFlyTheShortestDistance) {
  std::mt19937 rng(7);
  DistanceService service = random_service(rng, 15, 9, true);
  TargetSearch search;
  search.bind(&service);
  const Grid<std::uint8_t>& allowed = service.allowed_mask();
  for (int t = 0; t < allowed.size(); t += 5) {
    const Cell to = allowed.cell(t);
    for (int f = 0; f < allowed.size(); f += 3) {
      Cell at = allowed.cell(f);
      const int expected = service.distance(at, to);
      if (!service.allowed(at) || !service.allowed(to) || expected >= kUnreachable) continue;
      int flown = 0;
      while (at != to) {
        const Cell next = search.next_step(at, to);
        ASSERT_NE(next, at);
        flown += service.flight_table().between(at, next);
        at = next;
      }
      EXPECT_EQ(flown, expected);
    }
  }
}

// Towards a target a few cells away on a long grid the search reaches only the positions about as
// near to the target, not the grid.
TEST(TargetSearch, ANearTargetIsFoundWithoutSearchingTheGrid) {
  Grid<std::uint8_t> allowed(400, 20, 1);
  allowed(200, 10) = 0;  // one no-fly position: distances are searched
  DistanceService service(allowed);
  ASSERT_TRUE(service.searched());
  TargetSearch search;
  search.bind(&service);
  EXPECT_EQ(search.next_step({100, 5}, {104, 5}), (Cell{101, 5}));
  // Distances up to 4 from (104, 5): at most 2·4·5 + 1 = 41 positions settled, plus their
  // neighbours reached at 5.
  EXPECT_LE(search.reached(), 41u + 4u * 5u + 4u);
  EXPECT_EQ(service.searches(), 0);
  EXPECT_EQ(search.next_step({101, 5}, {104, 5}), (Cell{102, 5}));
  EXPECT_LE(search.reached(), 41u + 4u * 5u + 4u);
}

// Without no-fly positions or long flights every answer is the Manhattan rule's, with no search.
TEST(TargetSearch, ManhattanDistancesNeedNoSearch) {
  DistanceService service(30, 10);
  TargetSearch search;
  search.bind(&service);
  EXPECT_EQ(search.next_step({3, 4}, {9, 1}), (Cell{4, 4}));
  EXPECT_EQ(search.next_step({9, 4}, {9, 1}), (Cell{9, 3}));
  EXPECT_EQ(search.next_step({9, 1}, {9, 1}), (Cell{9, 1}));
  EXPECT_EQ(search.reached(), 0u);
}

}  // namespace
}  // namespace hullinspect::grid
