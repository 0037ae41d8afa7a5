#pragma once
// A small hull whose grid closes on itself, for tests of the seam (docs/hulls.md "Neighbours"):
// a text mask wrapped round a vertical cylinder whose circumference is the grid's width, so that
// column 0 and column W − 1 meet and every row's two ends are linked across the seam.

#include <string_view>

#include "hullinspect/world/hull.hpp"

namespace hullinspect::testing {

/// The mask `text` (parse_text_mask: rows top first, 'X' hull) as an unrolled hull of cells of
/// `cell_size` metres on a cylinder, each cell's normal pointing out from the axis, with its seam.
world::HullMask seam_cylinder_hull(std::string_view text, double cell_size = 1.0);

}  // namespace hullinspect::testing
