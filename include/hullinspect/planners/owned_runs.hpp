#pragma once
// One UAV's cells of an owner grid as runs along a band axis, so that band_sweep's bands of them,
// and of them less an approach's footprints, are read per line and per run, not per cell
// (Sweep-Inspect plans several candidate sweeps over one region: docs/sweep-inspect.md,
// "Where it starts").

#include <cstdint>
#include <span>
#include <vector>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/planners/band_sweep.hpp"

namespace hullinspect::planners {

/// The runs of consecutive cells one UAV owns on each line across the bands: a row of the grid
/// for row bands, a column for column bands, each run from `lo` to `hi` along the band.
class OwnedRuns {
 public:
  /// Reads the cells where `owner` is `uav` in columns [x_lo, x_hi] (x_hi < 0: up to the last),
  /// once each.
  void build(const grid::Grid<std::int16_t>& owner, int uav, BandAxis axis, int x_lo = 0,
             int x_hi = -1);
  /// The bounding box of the cells read (x_hi < 0: none).
  LegBox box() const;
  /// region_bands(owner, uav, s, axis, band_start, x_lo, x_hi) of the grid read by build, with
  /// the cells inside any of the `removed` boxes left out.
  RegionBands bands(int s, std::span<const int> band_start,
                    std::span<const LegBox> removed = {}) const;

 private:
  struct Run {
    int lo;
    int hi;
  };
  /// Along one line (across coordinate `line`), its first / last cell in none of the intervals
  /// `gaps` along it (−1: none).
  int first_kept(int line, std::span<const BandExtent> gaps) const;
  int last_kept(int line, std::span<const BandExtent> gaps) const;
  BandAxis axis_ = BandAxis::kColumns;
  int across_size_ = 0;
  std::vector<std::vector<Run>> runs_;  // per line across the bands, in order along it
  int line_lo_ = 0;                     // the first and last line with a run (hi < lo: none)
  int line_hi_ = -1;
  mutable std::vector<BandExtent> kept_;  // scratch of bands: per line, its first and last kept
  mutable std::vector<BandExtent> gaps_;  // scratch of bands: one line's removed intervals
};

}  // namespace hullinspect::planners
