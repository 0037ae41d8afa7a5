#pragma once
// Which neighbour a move towards a target takes on a field of distances to that target: shared by
// the whole-grid field of DistanceService::next_step() and the bounded TargetSearch.

#include <cstdint>

#include "hullinspect/grid/flight_steps.hpp"
#include "hullinspect/grid/grid.hpp"

namespace hullinspect::grid::detail {

/// The allowed 4-neighbour of `from` on a shortest path to `to`, `field` holding distances to `to`
/// (final at `from` and at every position nearer to `to`; never below the true distance
/// elsewhere): along x towards `to` first, then along y, then east, west, north, south. `from`
/// when `from == to` or it has no distance.
inline Cell step_on_field(Cell from, Cell to, const Grid<std::uint8_t>& allowed,
                          const EdgeSteps& steps, const Grid<int>& field) {
  if (from == to) return from;
  Cell preferred[6];
  int count = 0;
  if (to.x != from.x) preferred[count++] = {from.x + (to.x > from.x ? 1 : -1), from.y};
  if (to.y != from.y) preferred[count++] = {from.x, from.y + (to.y > from.y ? 1 : -1)};
  for (int d = 0; d < 4; ++d) {
    preferred[count++] = neighbour(from, d, allowed.width(), allowed.height(), steps);
  }
  const int here = field[from];
  if (here >= kUnreachable) return from;
  for (int i = 0; i < count; ++i) {
    const Cell n = preferred[i];
    if (allowed.contains(n) && allowed[n] != 0 && field[n] == here - steps.between(from, n)) {
      return n;
    }
  }
  return from;
}

}  // namespace hullinspect::grid::detail
