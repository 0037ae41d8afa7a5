#pragma once
// How many steps a flight between two 4-neighbour grid positions takes (docs/model.md "Neighbour
// flights"). On a flat or one-side hull every neighbour is one step away and the table is empty.
// On an unrolled hull the UAV stands off at S + ζ_z·n from a curved surface, so around the bow and
// the stern two neighbouring positions can be several cells apart: such a flight takes
// ceil(distance / cell) steps on that plane.
//
// A grid that closes on itself (an unrolled hull with its transom) has a seam: column 0 and column
// W − 1 of a linked row meet, and the flight between them is one more neighbour flight, at its
// stand-off length like the others. neighbour() is the one place that says which positions are
// 4-neighbours, across the seam included; every search, move and check asks it.

#include <array>
#include <cstdint>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/grid/grid.hpp"

namespace hullinspect::grid {

/// The longest neighbour flight a table holds, in steps (longer flights are clamped to it).
inline constexpr int kMaxFlightSteps = 255;

/// A flight up to this fraction of a cell longer than a whole number of cells still takes that
/// number of steps: the unrolled grid's columns and rows are a cell apart only to within the
/// unrolling's rounding, and a flight 1 % over a cell is not a second step.
inline constexpr double kFlightSlackCells = 0.05;

/// Steps of a neighbour flight of `cells` cells: max(1, ceil(cells − kFlightSlackCells)), at most
/// kMaxFlightSteps.
int flight_steps_for(double cells);

/// Per edge steps on one plane: east(x, y) from (x, y) to (x + 1, y), north(x, y) from (x, y) to
/// (x, y + 1); 1 beyond the grid's last column or row. seam[y], on a grid that closes on itself,
/// is the flight between (W − 1, y) and (0, y) (0: that row is not linked); empty on any other.
struct EdgeSteps {
  Grid<std::uint8_t> east;
  Grid<std::uint8_t> north;
  std::vector<std::uint8_t> seam;

  bool empty() const { return east.size() == 0; }
  /// True when row y's two ends are neighbours across the seam.
  bool seam_links(int y) const {
    return y >= 0 && static_cast<std::size_t>(y) < seam.size() &&
           seam[static_cast<std::size_t>(y)] != 0;
  }
  /// Steps from `a` to its 4-neighbour `b` (1 when the table is empty). Two positions of a row
  /// more than a column apart are the seam's two ends.
  int between(Cell a, Cell b) const {
    if (empty()) return 1;
    if (b.y == a.y) {
      if (b.x - a.x > 1 || a.x - b.x > 1) return seam[static_cast<std::size_t>(a.y)];
      return east(b.x > a.x ? a.x : b.x, a.y);
    }
    return north(a.x, b.y > a.y ? a.y : b.y);
  }
  /// The longest flight in the table (1 when empty).
  int longest() const;
};

/// The 4-neighbour of `c` in direction d (kNeighbourDx/Dy order: east, west, north, south) on a
/// width × height grid with the flights `steps`: across a linked seam west of column 0 is column
/// W − 1 and east of column W − 1 is column 0. kNoCell when that neighbour is off the grid.
inline Cell neighbour(Cell c, int d, int width, int height, const EdgeSteps& steps) {
  Cell n{c.x + kNeighbourDx[d], c.y + kNeighbourDy[d]};
  if (n.y < 0 || n.y >= height) return kNoCell;
  if (n.x < 0 || n.x >= width) {
    if (!steps.seam_links(n.y)) return kNoCell;
    n.x = n.x < 0 ? width - 1 : 0;
  }
  return n;
}

/// True when `a` and `b` are 4-neighbours on the grid of the flights `steps` (across its seam
/// included; a table with a seam spans the whole grid).
inline bool adjacent(Cell a, Cell b, const EdgeSteps& steps) {
  if (manhattan(a, b) == 1) return true;
  const int last = steps.east.width() - 1;
  return a.y == b.y && steps.seam_links(a.y) && last > 1 &&
         ((a.x == 0 && b.x == last) || (b.x == 0 && a.x == last));
}

/// The neighbour flights of both planes. Empty when every neighbour is one step away on both, so
/// that such hulls pay nothing.
struct FlightSteps {
  std::array<EdgeSteps, 2> plane;  ///< [z − 1]

  bool empty() const { return plane[0].empty(); }
  /// True when the grid closes on itself at a seam (both planes link the same rows).
  bool has_seam() const { return !plane[0].seam.empty(); }
  int between(Cell a, Cell b, int z) const {
    return plane[static_cast<std::size_t>(z - 1)].between(a, b);
  }
  /// Per edge the longer of the two planes' flights: what a plan that may fly either plane
  /// budgets (the distance service's weights).
  EdgeSteps longer_plane() const;
};

/// Per grid position a point and unit normal (ship frame, metres) a UAV on plane z stands off from
/// at point + ζ_z·normal.
struct StandoffPoints {
  Grid<std::array<double, 3>> point;
  Grid<std::array<double, 3>> normal;
  /// The grid closes on itself: every row's two ends are neighbours across the seam.
  bool seam = false;
};

/// ζ in metres of the plane whose footprint side is `side` cells: side·cell / (2·tan(θ/2)).
double standoff_m(int side, double cell_m, double theta_deg);

/// The flight steps between the stand-off positions of every two 4-neighbours on both planes
/// (footprint sides s1, s2, aperture θ), and across the seam when `points.seam` (a grid at least
/// three columns wide); empty when no flight is longer than one step, there is no seam, or
/// `points` is empty. The simulator and the trace reader compute a mission's table with this one
/// function from the same numbers, so they agree on every flight.
FlightSteps flight_steps(const StandoffPoints& points, double cell_m, double theta_deg, int s1,
                         int s2);

}  // namespace hullinspect::grid
