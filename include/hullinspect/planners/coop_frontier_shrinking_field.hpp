#pragma once
// The Manhattan distance field to a cell set that loses members (the prior's corrosion cells leave
// d_HP's set as they are seen), recomputed only in a window around the removed members instead of
// over the whole grid.
//
// Removing a member s can only change the cells that had s as a nearest member, the cells c with
// d(c) = |c − s|. That set holds, with each of its cells, every monotone (staircase) path from s to
// it, so its extent in x is that of its part of s's row and its extent in y that of its part of
// s's column: two short walks from s bound it. In the window of those bounds for every removed
// member, grown by one cell, the cells of the added ring keep their distance (no removed member was
// nearest to them) and every shortest path from inside the window to a member outside crosses the
// ring. So the two-pass transform of the window, started from the members inside it (0), the
// ring's distances and nothing elsewhere, gives the exact field there: the same as a transform of
// the whole grid.

#include <cstdint>
#include <span>

#include "hullinspect/grid/grid.hpp"

namespace hullinspect::planners {

/// A rectangle of cells, bounds included.
struct CellWindow {
  int x0 = 0;
  int x1 = -1;
  int y0 = 0;
  int y1 = -1;
  bool empty() const { return x1 < x0 || y1 < y0; }
  long long area() const {
    return empty() ? 0 : static_cast<long long>(x1 - x0 + 1) * static_cast<long long>(y1 - y0 + 1);
  }
};

/// The cells whose distance can change when `removed` member cells leave the set behind the exact
/// field `distance` (the window of the header comment, without its ring).
CellWindow affected_window(std::span<const int> removed, const grid::Grid<int>& distance);

/// `distance` is the exact Manhattan distance field (grid::kUnreachable everywhere for an empty
/// set) to a set that has since lost the cells `removed` (no cell added); `members` is the set
/// now. Makes `distance` the exact field of the set now, recomputing only the affected window and
/// its ring. Returns the number of cells recomputed.
long long remove_members(std::span<const int> removed, const grid::Grid<std::uint8_t>& members,
                         grid::Grid<int>& distance);

}  // namespace hullinspect::planners
