#pragma once
// How many steps a flight between two 4-neighbour grid positions takes (docs/model.md "Neighbour
// flights"). On a flat or one-side hull every neighbour is one step away and the table is empty.
// On an unrolled hull the UAV stands off at S + ζ_z·n from a curved surface, so around the bow and
// the stern two neighbouring positions can be several cells apart: such a flight takes
// ceil(distance / cell) steps on that plane.

#include <array>
#include <cstdint>

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
/// (x, y + 1); 1 beyond the grid's last column or row.
struct EdgeSteps {
  Grid<std::uint8_t> east;
  Grid<std::uint8_t> north;

  bool empty() const { return east.size() == 0; }
  /// Steps from `a` to its 4-neighbour `b` (1 when the table is empty).
  int between(Cell a, Cell b) const {
    if (empty()) return 1;
    if (b.y == a.y) return east(b.x > a.x ? a.x : b.x, a.y);
    return north(a.x, b.y > a.y ? a.y : b.y);
  }
  /// The longest flight in the table (1 when empty).
  int longest() const;
};

/// The neighbour flights of both planes. Empty when every neighbour is one step away on both, so
/// that such hulls pay nothing.
struct FlightSteps {
  std::array<EdgeSteps, 2> plane;  ///< [z − 1]

  bool empty() const { return plane[0].empty(); }
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
};

/// ζ in metres of the plane whose footprint side is `side` cells: side·cell / (2·tan(θ/2)).
double standoff_m(int side, double cell_m, double theta_deg);

/// The flight steps between the stand-off positions of every two 4-neighbours on both planes
/// (footprint sides s1, s2, aperture θ); empty when no flight is longer than one step or `points`
/// is empty. The simulator and the trace reader compute a mission's table with this one function
/// from the same numbers, so they agree on every flight.
FlightSteps flight_steps(const StandoffPoints& points, double cell_m, double theta_deg, int s1,
                         int s2);

}  // namespace hullinspect::grid
