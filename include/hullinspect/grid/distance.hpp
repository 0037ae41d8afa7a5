#pragma once
// Shortest 4-neighbour paths and connected components on a passability mask. The overloads with
// an EdgeSteps table also step across its seam (grid::neighbour): on a grid that closes on itself
// a row's two ends are neighbours, so a region or a flight space may be joined only across it.

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "hullinspect/grid/flight_steps.hpp"
#include "hullinspect/grid/grid.hpp"

namespace hullinspect::grid {

inline constexpr int kUnreachable = std::numeric_limits<int>::max() / 4;

/// Reusable work space so repeated distance transforms allocate nothing.
struct BfsScratch {
  std::vector<int> queue;
};

/// Breadth-first distance (in 4-neighbour steps through cells with passable != 0) from the nearest
/// source index. Unreachable and impassable cells get kUnreachable. `out` is resized if needed.
void bfs_distances(const Grid<std::uint8_t>& passable, std::span<const int> sources, Grid<int>& out,
                   BfsScratch& scratch);

/// Labels the 4-connected components of the cells with mask != 0 as 0, 1, 2, … in order of their
/// first cell in (y, x) order; other cells get -1. Returns the number of components.
int label_components(const Grid<std::uint8_t>& mask, Grid<int>& labels, BfsScratch& scratch);

/// bfs_distances() whose neighbours are grid::neighbour()'s on the grid of `links`: across its
/// seam too (every step counts one; the table's flight lengths are not weights here). Without a
/// seam the same as bfs_distances().
void bfs_distances(const Grid<std::uint8_t>& passable, std::span<const int> sources, Grid<int>& out,
                   BfsScratch& scratch, const EdgeSteps& links);

/// label_components() with grid::neighbour()'s neighbours on the grid of `links` (across its seam
/// too). Without a seam the same as label_components().
int label_components(const Grid<std::uint8_t>& mask, Grid<int>& labels, BfsScratch& scratch,
                     const EdgeSteps& links);

}  // namespace hullinspect::grid
