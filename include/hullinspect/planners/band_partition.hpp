#pragma once
// Sweep-Inspect's band partition (docs/sweep-inspect.md, "Regions"): the hull's column bands flown
// as one boustrophedon, cut into n consecutive pieces of equal expected work. A piece ends in the
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
/// takes the row. With `offset` (per UAV, by id; empty: none) a UAV's piece is short of the others'
/// by its offset (work it has besides the piece, in the same unit), so that piece plus offset is
/// the same for every UAV. Throws Error when there are fewer rows than UAVs or a piece is not
/// 4-connected (a column of the hull that is not one run of cells can cut one).
partition::Partition band_order_partition(const world::HullMask& hull,
                                          const grid::Grid<double>& extra,
                                          std::span<const int> band_start,
                                          std::span<const grid::Cell> starts, double row_cost,
                                          double band_cost, std::span<const double> offset = {});

/// The rows of band_order_partition's boustrophedon and pieces cut between them: piece j (the
/// j-th along the hull) goes to uav_of_piece(j), and a cut is the first row of the next piece.
class BandPieces {
 public:
  /// As band_order_partition's arguments; throws Error when there are fewer rows than UAVs.
  BandPieces(const world::HullMask& hull, const grid::Grid<double>& extra,
             std::span<const int> band_start, std::span<const grid::Cell> starts, double row_cost,
             double band_cost);
  std::size_t rows() const { return row_work_.size(); }
  int uavs() const { return static_cast<int>(uav_of_piece_.size()); }
  int uav_of_piece(int piece) const { return uav_of_piece_[static_cast<std::size_t>(piece)]; }
  /// The n − 1 cuts of band_order_partition (with its `offset`).
  std::vector<std::size_t> balanced_cuts(std::span<const double> offset = {}) const;
  /// The partition of `cuts` (increasing, every piece at least one row); its desired weights are
  /// the shares of `offset` as in balanced_cuts. Throws Error when a piece is not 4-connected.
  partition::Partition cut(std::span<const std::size_t> cuts,
                           std::span<const double> offset = {}) const;
  /// Sets the owner of the cells of rows [lo, hi) to k.
  void assign_rows(grid::Grid<std::int16_t>& owner, std::size_t lo, std::size_t hi, int k) const;
  /// The first and last column of the cells of rows [lo, hi) (rows of [lo, hi) must exist).
  std::pair<int, int> columns(std::size_t lo, std::size_t hi) const;
  /// The work of rows [lo, hi), and the `extra` part of it.
  double work(std::size_t lo, std::size_t hi) const;
  double extra(std::size_t lo, std::size_t hi) const {
    return extra_before_[hi] - extra_before_[lo];
  }

 private:
  static double offset_of(std::span<const double> offset, int k) {
    return offset.empty() ? 0.0 : offset[static_cast<std::size_t>(k)];
  }
  /// What every UAV's piece plus its offset comes to: (total + offsets) / n.
  double common_share(std::span<const double> offset) const;
  const world::HullMask* hull_;
  std::vector<int> order_;  // hull cells in the boustrophedon's order
  std::vector<std::size_t> row_begin_;
  std::vector<double> row_work_;
  std::vector<double> extra_before_;  // prefix sums of the rows' extra work
  double total_ = 0;
  std::vector<int> uav_of_piece_;
};

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
