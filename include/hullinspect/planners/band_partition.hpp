#pragma once
// Sweep-Inspect's band partition (docs/beyond.md, band-partition): the hull's column bands flown as
// one boustrophedon, cut into n consecutive pieces of equal expected work. A piece ends in the
// middle of a band (its lower or upper rows), so no UAV pays a whole pass of the hull's height for
// a band its slab only clips — which column slabs of arbitrary width do at each slab's edge.

#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/partition/partitioner.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::planners {

/// The hull's column bands: each run of columns of one band width (`width_of_column`, e.g. s1 in
/// dense columns and s2 elsewhere) is cut into bands of that width from the run's first column.
/// Returns, per column, the first column of its band.
std::vector<int> column_band_starts(std::span<const int> width_of_column);

/// Cells in the order of one boustrophedon over the bands (`band_start` from column_band_starts):
/// bands left to right, the first flown up (rows ascending), the next down, and so on; within a
/// row of a band, left to right. The work of a piece: `row_cost` per row of a band (one step of
/// its flight, however many cells the row holds), `band_cost` per band (the flight to it), and
/// each cell's `extra` (e.g. the inspections expected there; empty: none). Every piece is then
/// cut, at the start of a row, where the running sum is nearest k/n of the total, the pieces
/// going to the UAVs in the order of their starts' x (as the stripes partitioner's slabs); a tie
/// takes the row. Throws Error when there are fewer rows than UAVs or a piece is not 4-connected
/// (a column of the hull that is not one run of cells can cut one).
partition::Partition band_order_partition(const world::HullMask& hull,
                                          const grid::Grid<double>& extra,
                                          std::span<const int> band_start,
                                          std::span<const grid::Cell> starts, double row_cost,
                                          double band_cost);

/// The smallest end t (within 0.25, by doubling then bisection) for which `fits(t)` holds, `fits`
/// growing with t: the common end of a split in which every UAV's work must fit.
double earliest_common_end(const std::function<bool(double)>& fits);

/// Splits `cells` (flat indices of a grid `width` wide; sorted here into the boustrophedon's
/// order of `band_start`, as band_order_partition's) into consecutive runs, one per UAV of `uavs`
/// (id and position, in the order the runs go to them): the earliest common end t for which
/// each UAV's `load` (by id), its flight to the nearer end of its run (Manhattan) and its run's
/// work (`row_cost` per row of a band it holds a cell of, `band_cost` per band begun) fit in t,
/// found by bisection. Calls assign(uav, cell) for every cell. (Sweep-Inspect's re-split at a
/// failure, on the band partition's grid.)
void split_in_band_order(std::vector<int>& cells, int width, std::span<const int> band_start,
                         std::span<const std::pair<int, grid::Cell>> uavs,
                         std::span<const double> load, double row_cost, double band_cost,
                         const std::function<void(int, int)>& assign);

}  // namespace hullinspect::planners
