#pragma once
// The detection-plane sweep of Sweep-Inspect (docs/sweep-inspect.md, "The sweep"): a boustrophedon
// over one UAV's cells in bands of s cells, flown along each band's centre line only as far as the
// footprint needs.

#include <cstdint>
#include <span>
#include <vector>

#include "hullinspect/grid/grid.hpp"

namespace hullinspect::planners {

enum class BandAxis {
  kRows,     ///< bands of s rows from the grid's bottom, flown along x (the lawnmower's pattern)
  kColumns,  ///< bands of s columns from the region's leftmost column, flown along y
};

/// The waypoints of a sweep at footprint side `s` (odd) over the cells where `owner` is `uav`,
/// from `from`: one band after the other (in order along the band axis), each flown along its
/// centre line from its nearer end. With `trim_ends` a band is flown only between the first and
/// last positions whose footprint (half-width (s − 1)/2) reaches its extent, instead of from end
/// cell to end cell: on the default hull's 30 rows a column band is then 23 moves long, not 29.
/// Column bands start at the region's leftmost column, so that a region of width w needs
/// ceil(w / s) of them; with `band_start` (per column, the first column of its band: a band grid
/// shared by the regions, column_band_starts in band_partition.hpp) at the band of the region's
/// leftmost column instead. Returns no waypoints when the UAV owns no cell. Only the columns
/// [x_lo, x_hi] of `owner` are read (x_hi < 0: up to the last), which must hold all the UAV's.
std::vector<grid::Cell> band_sweep(const grid::Grid<std::int16_t>& owner, int uav, int s,
                                   BandAxis axis, bool trim_ends, grid::Cell from,
                                   std::span<const int> band_start = {}, int x_lo = 0,
                                   int x_hi = -1);

/// One band's cells along it (x for row bands): the first and the last; hi < 0 when it holds none.
struct BandExtent {
  int lo = 0;
  int hi = -1;
};

/// The bands of one UAV's cells, as band_sweep cuts them: band j spans the across coordinates
/// [origin + j·s, origin + (j + 1)·s) and is flown along its centre line.
struct RegionBands {
  int origin = 0;
  std::vector<BandExtent> bands;
};

/// band_sweep's bands (same arguments); no bands when the UAV owns no cell.
RegionBands region_bands(const grid::Grid<std::int16_t>& owner, int uav, int s, BandAxis axis,
                         std::span<const int> band_start = {}, int x_lo = 0, int x_hi = -1);

/// band_sweep's waypoints over the given bands of a grid `across_size` bands' cells wide (the
/// grid's height for row bands, its width for column bands).
std::vector<grid::Cell> sweep_bands(const RegionBands& region, int s, BandAxis axis, bool trim_ends,
                                    grid::Cell from, int across_size);

/// Manhattan length of a flight from `from` through `waypoints` (how strips=auto compares two
/// sweeps).
int flight_length(grid::Cell from, const std::vector<grid::Cell>& waypoints);

/// The box of cells that a footprint of half-width `half` sees along the straight leg from `a`
/// to `b`, clipped to a `width` × `height` grid (corners inclusive).
struct LegBox {
  int x_lo = 0;
  int x_hi = -1;
  int y_lo = 0;
  int y_hi = -1;
};
LegBox leg_footprints(grid::Cell a, grid::Cell b, int half, int width, int height);

}  // namespace hullinspect::planners
