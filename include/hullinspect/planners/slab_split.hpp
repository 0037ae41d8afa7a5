#pragma once
// Sweep-Inspect's re-split at a failure off the band partition's grid (docs/sweep-inspect.md,
// "Failures"): the cells not yet observed go to the working UAVs in column slabs that end
// together. (On the band partition's grid: split_in_band_order, band_partition.hpp.)

#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "hullinspect/grid/grid.hpp"

namespace hullinspect::planners {

/// Splits `cells` (flat indices of a grid `width` wide, sorted by column) into consecutive column
/// slabs, left to right, one per UAV of `uavs` (id and position, in the order the slabs go to
/// them): the earliest common end t for which each UAV's `load` (by id), its flight to the nearer
/// end of its slab (`per_column` per column) and its slab (1 per cell) fit in t, found by
/// bisection. Calls assign(uav, cell) for every cell.
void split_in_slabs(std::span<const int> cells, int width,
                    std::span<const std::pair<int, grid::Cell>> uavs, std::span<const double> load,
                    double per_column, const std::function<void(int, int)>& assign);

}  // namespace hullinspect::planners
