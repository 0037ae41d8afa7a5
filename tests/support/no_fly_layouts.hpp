#pragma once
// Building blocks of the no-fly test layouts shared by the partition and mission tests: a small
// hull with a keel line and rectangles of no-fly positions.

#include <cstdint>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::testing {

using NoFlyMask = grid::Grid<std::uint8_t>;

/// Marks the positions of the rectangle (x0, y0)–(x1, y1), corners inclusive, no-fly.
void no_fly_box(NoFlyMask& mask, int x0, int y0, int x1, int y1);

/// A 60 × 20 hull: a full rectangle except the two bottom corners (a hull-like keel line).
const world::HullMask& small_keel_hull();

}  // namespace hullinspect::testing
