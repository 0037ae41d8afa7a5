// Neighbour flights (grid/flight_steps.hpp): how many steps a flight between stand-off positions
// takes, and the distance service's shortest paths when some flights take several steps.
#include "hullinspect/grid/flight_steps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "hullinspect/grid/distance_service.hpp"

namespace hullinspect::grid {
namespace {

TEST(FlightSteps, AFlightTakesItsLengthInCellsRoundedUpBeyondTheSlack) {
  EXPECT_EQ(flight_steps_for(0.0), 1);
  EXPECT_EQ(flight_steps_for(1.0), 1);
  EXPECT_EQ(flight_steps_for(1.0 + kFlightSlackCells), 1);
  EXPECT_EQ(flight_steps_for(1.1), 2);
  EXPECT_EQ(flight_steps_for(3.5), 4);
  EXPECT_EQ(flight_steps_for(1e9), kMaxFlightSteps);
}

// Three positions in a row on a right-angled corner: the surface turns by 90° between x = 1 and
// x = 2, so the stand-off positions there lie ζ·√2 apart, farther on the outer plane.
StandoffPoints corner() {
  StandoffPoints p;
  p.point = Grid<std::array<double, 3>>(3, 2);
  p.normal = Grid<std::array<double, 3>>(3, 2);
  for (int y = 0; y < 2; ++y) {
    p.point(0, y) = {-1.0, 0.0, double(y)};
    p.point(1, y) = {0.0, 0.0, double(y)};
    p.point(2, y) = {0.0, 0.0, double(y)};  // the corner's other face starts at the same edge
    p.normal(0, y) = {0.0, -1.0, 0.0};
    p.normal(1, y) = {0.0, -1.0, 0.0};
    p.normal(2, y) = {1.0, 0.0, 0.0};
  }
  return p;
}

TEST(FlightSteps, AroundACornerTheOuterPlaneFliesFarther) {
  // θ = 90°: ζ = s·cell / 2, so ζ1 = 2.5 and ζ2 = 3.5 cells of 1 m.
  const FlightSteps f = flight_steps(corner(), 1.0, 90.0, 5, 7);
  ASSERT_FALSE(f.empty());
  EXPECT_EQ(f.between({0, 0}, {1, 0}, 1), 1);
  EXPECT_EQ(f.between({1, 0}, {2, 0}, 1), static_cast<int>(std::ceil(2.5 * std::sqrt(2.0))));
  EXPECT_EQ(f.between({2, 0}, {1, 0}, 2), static_cast<int>(std::ceil(3.5 * std::sqrt(2.0))));
  EXPECT_EQ(f.between({1, 0}, {1, 1}, 2), 1);  // straight up the face
  EXPECT_EQ(f.longer_plane().between({1, 1}, {2, 1}), 5);
  // A flat surface: every flight one step, so the table is empty and nothing pays for it.
  StandoffPoints flat = corner();
  flat.point(2, 0) = {1.0, 0.0, 0.0};
  flat.point(2, 1) = {1.0, 0.0, 1.0};
  flat.normal(2, 0) = flat.normal(2, 1) = {0.0, -1.0, 0.0};
  EXPECT_TRUE(flight_steps(flat, 1.0, 90.0, 5, 7).empty());
}

// A tiny deterministic generator for test grids.
struct Lcg {
  std::uint64_t state;
  int below(int n) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<int>((state >> 33) % static_cast<std::uint64_t>(n));
  }
};

// Reference: relax d[n] = min(d[n], d[c] + steps(c, n)) over the whole grid until nothing
// changes; only allowed cells and the source pass a path on.
Grid<int> relaxed(const Grid<std::uint8_t>& allowed, const EdgeSteps& steps, Cell source) {
  Grid<int> d(allowed.width(), allowed.height(), kUnreachable);
  d[source] = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (int i = 0; i < d.size(); ++i) {
      const Cell c = d.cell(i);
      if (d[i] >= kUnreachable || (allowed[i] == 0 && c != source)) continue;
      for (const Cell n :
           {Cell{c.x + 1, c.y}, Cell{c.x - 1, c.y}, Cell{c.x, c.y + 1}, Cell{c.x, c.y - 1}}) {
        if (!d.contains(n)) continue;
        const int via = d[i] + steps.between(c, n);
        if (via < d[n]) {
          d[n] = via;
          changed = true;
        }
      }
      // The seam, written out on its own: a row's two ends are neighbours where it is linked.
      const int last = d.width() - 1;
      if (steps.seam_links(c.y) && (c.x == 0 || c.x == last)) {
        const Cell n{c.x == 0 ? last : 0, c.y};
        const int via = d[i] + steps.seam[static_cast<std::size_t>(c.y)];
        if (via < d[n]) {
          d[n] = via;
          changed = true;
        }
      }
    }
  }
  return d;
}

TEST(FlightSteps, TheDistanceServiceAddsUpTheFlightsOfItsShortestPaths) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE(seed);
    Lcg rng{seed};
    const int w = 9, h = 6;
    Grid<std::uint8_t> allowed(w, h, 1);
    EdgeSteps steps{Grid<std::uint8_t>(w, h, 1), Grid<std::uint8_t>(w, h, 1), {}};
    for (int i = 0; i < allowed.size(); ++i) {
      if (seed % 2 == 0 && rng.below(100) < 15) allowed[i] = 0;
      if (rng.below(4) == 0) steps.east[i] = static_cast<std::uint8_t>(2 + rng.below(6));
      if (rng.below(4) == 0) steps.north[i] = static_cast<std::uint8_t>(2 + rng.below(6));
    }
    // From the third seed on the grid closes on itself: most rows linked across the seam.
    if (seed >= 3) {
      steps.seam.resize(static_cast<std::size_t>(h));
      for (auto& seam : steps.seam) {
        seam = static_cast<std::uint8_t>(rng.below(4) == 0 ? 0 : 1 + rng.below(5));
      }
    }
    DistanceService service(allowed, steps);
    ASSERT_TRUE(service.searched());
    for (int s = 0; s < allowed.size(); s += 7) {
      const Cell source = allowed.cell(s);
      const Grid<int> expected = relaxed(allowed, steps, source);
      const Grid<int> field = service.field(source);
      ASSERT_EQ(field, expected) << "from (" << source.x << ", " << source.y << ")";
      // Following next_step from every allowed position flies exactly the distance.
      for (int t = 0; t < allowed.size(); ++t) {
        const Cell from = allowed.cell(t);
        if (!service.allowed(from) || !service.allowed(source) || expected[t] >= kUnreachable)
          continue;
        std::vector<Cell> path;
        ASSERT_TRUE(service.append_path(from, source, path));
        int flown = 0;
        Cell at = from;
        for (const Cell next : path) {
          flown += steps.between(at, next);
          at = next;
        }
        EXPECT_EQ(flown, expected[t]);
      }
    }
  }
}

TEST(FlightSteps, ALongFlightIsFlownAroundWhenThatIsShorter) {
  // Two rows; in the lower one (1, 0) → (2, 0) takes 5 steps: the path climbs to the upper row.
  EdgeSteps steps{Grid<std::uint8_t>(4, 2, 1), Grid<std::uint8_t>(4, 2, 1), {}};
  steps.east(1, 0) = 5;
  DistanceService service(Grid<std::uint8_t>(4, 2, 1), steps);
  EXPECT_EQ(service.distance({0, 0}, {3, 0}), 5);  // up, three east, down
  EXPECT_EQ(service.next_step({1, 0}, {2, 0}), (Cell{1, 1}));
  EXPECT_EQ(service.distance({1, 0}, {2, 0}), 3);
  // Without a table the service is the Manhattan one and searches nothing.
  DistanceService plain(Grid<std::uint8_t>(4, 2, 1), EdgeSteps{});
  EXPECT_FALSE(plain.searched());
  EXPECT_EQ(plain.distance({0, 0}, {3, 0}), 3);
  EXPECT_EQ(plain.searches(), 0);
}

// distances_to() gives the reference distances to a few targets, with and without no-fly
// positions and long flights, from sources with and without a cached field, runs no whole-grid
// search of its own and leaves the cache as it was.
TEST(FlightSteps, DistancesToAFewTargetsEqualTheFieldsWithoutCachingOne) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    SCOPED_TRACE(seed);
    Lcg rng{seed};
    const int w = 5 + rng.below(20), h = 3 + rng.below(12);
    Grid<std::uint8_t> allowed(w, h, 1);
    EdgeSteps steps;
    if (seed % 4 != 0) {
      steps.east = Grid<std::uint8_t>(w, h, 1);
      steps.north = Grid<std::uint8_t>(w, h, 1);
    }
    for (int i = 0; i < allowed.size(); ++i) {
      if (seed % 2 == 0 && rng.below(100) < 20) allowed[i] = 0;
      if (!steps.empty() && rng.below(4) == 0) {
        steps.east[i] = static_cast<std::uint8_t>(2 + rng.below(6));
      }
      if (!steps.empty() && rng.below(4) == 0) {
        steps.north[i] = static_cast<std::uint8_t>(2 + rng.below(6));
      }
    }
    DistanceService service(allowed, steps);
    if (!service.searched()) continue;
    for (int s = 0; s < allowed.size(); s += 3) {
      const Cell source = allowed.cell(s);
      const Grid<int> expected = relaxed(allowed, steps, source);
      std::vector<Cell> targets;
      for (int t = 0, count = 1 + rng.below(6); t < count; ++t) {
        targets.push_back(allowed.cell(rng.below(allowed.size())));
      }
      targets.push_back(targets.front());  // a target twice
      std::vector<int> got(targets.size(), -1);
      const long long searches = service.searches();
      service.distances_to(source, targets, got);
      EXPECT_EQ(service.searches(), searches);
      for (std::size_t t = 0; t < targets.size(); ++t) {
        EXPECT_EQ(got[t], expected[targets[t]])
            << "from (" << source.x << ", " << source.y << ") to (" << targets[t].x << ", "
            << targets[t].y << ")";
      }
    }
    // From a source whose field is cached, the field is read.
    const Cell source = allowed.cell(0);
    const Grid<int> field = service.field(source);
    const std::vector<Cell> targets{allowed.cell(allowed.size() - 1), allowed.cell(w)};
    std::vector<int> got(2);
    service.distances_to(source, targets, got);
    EXPECT_EQ(got[0], field[targets[0]]);
    EXPECT_EQ(got[1], field[targets[1]]);
  }
}

// A ring: four positions in a row around a square of side 1 m, the first and last facing each
// other across the seam one cell apart at the surface.
StandoffPoints ring(bool seam) {
  StandoffPoints p;
  p.point = Grid<std::array<double, 3>>(4, 1);
  p.normal = Grid<std::array<double, 3>>(4, 1);
  p.point(0, 0) = {0.0, 0.5, 0.0};
  p.point(1, 0) = {0.5, 1.0, 0.0};
  p.point(2, 0) = {1.0, 0.5, 0.0};
  p.point(3, 0) = {0.5, 0.0, 0.0};
  p.normal(0, 0) = {-1.0, 0.0, 0.0};
  p.normal(1, 0) = {0.0, 1.0, 0.0};
  p.normal(2, 0) = {1.0, 0.0, 0.0};
  p.normal(3, 0) = {0.0, -1.0, 0.0};
  p.seam = seam;
  return p;
}

TEST(FlightSteps, TheSeamIsAFlightAtItsStandOffLength) {
  // θ = 90°, s = 2: ζ = 1 m. From (0.5 − 1, 0.5) facing −x to (0.5, −1) facing −y: √(1.5² + 1.5²).
  const FlightSteps f = flight_steps(ring(true), 1.0, 90.0, 2, 2);
  ASSERT_TRUE(f.has_seam());
  const int seam = flight_steps_for(std::hypot(1.5, 1.5));
  EXPECT_EQ(f.between({0, 0}, {3, 0}, 1), seam);
  EXPECT_EQ(f.between({3, 0}, {0, 0}, 2), seam);
  EXPECT_EQ(f.between({1, 0}, {2, 0}, 1), seam);  // a corner like the seam's
  // The seam's neighbours: west of column 0 is column 3 and east of column 3 is column 0.
  const EdgeSteps& e = f.plane[0];
  EXPECT_EQ(neighbour({0, 0}, 1, 4, 1, e), (Cell{3, 0}));
  EXPECT_EQ(neighbour({3, 0}, 0, 4, 1, e), (Cell{0, 0}));
  EXPECT_EQ(neighbour({0, 0}, 2, 4, 1, e), kNoCell);  // no row above
  EXPECT_TRUE(adjacent({0, 0}, {3, 0}, e));
  EXPECT_FALSE(adjacent({0, 0}, {2, 0}, e));
  // Around the ring the other way takes three flights: the service takes the seam.
  DistanceService service(Grid<std::uint8_t>(4, 1, 1), f.longer_plane());
  EXPECT_EQ(service.distance({0, 0}, {3, 0}), seam);
  EXPECT_EQ(service.next_step({0, 0}, {3, 0}), (Cell{3, 0}));
  // Without the seam the same points link nothing across, and the way round is the only one.
  const FlightSteps open = flight_steps(ring(false), 1.0, 90.0, 2, 2);
  EXPECT_FALSE(open.has_seam());
  EXPECT_EQ(neighbour({0, 0}, 1, 4, 1, open.plane[0]), kNoCell);
  EXPECT_FALSE(adjacent({0, 0}, {3, 0}, open.plane[0]));
  DistanceService around(Grid<std::uint8_t>(4, 1, 1), open.longer_plane());
  EXPECT_EQ(around.distance({0, 0}, {3, 0}), 3 * seam);
}

}  // namespace
}  // namespace hullinspect::grid
