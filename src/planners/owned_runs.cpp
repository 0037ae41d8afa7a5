#include "hullinspect/planners/owned_runs.hpp"

#include <algorithm>
#include <limits>

namespace hullinspect::planners {

void OwnedRuns::build(const grid::Grid<std::int16_t>& owner, int uav, BandAxis axis, int x_lo,
                      int x_hi) {
  axis_ = axis;
  const bool rows = axis == BandAxis::kRows;
  across_size_ = rows ? owner.height() : owner.width();
  // The lines keep their capacity from one build to the next.
  if (runs_.size() < static_cast<std::size_t>(across_size_))
    runs_.resize(static_cast<std::size_t>(across_size_));
  for (auto& line : runs_) line.clear();
  x_lo = std::max(0, x_lo);
  x_hi = x_hi < 0 ? owner.width() - 1 : std::min(owner.width() - 1, x_hi);
  // Row by row, so that the grid is read in its order; a cell extends the run its line ends
  // with when that run ends at the cell before it along the line.
  for (int y = 0; y < owner.height(); ++y) {
    for (int x = x_lo; x <= x_hi; ++x) {
      if (owner(x, y) != uav) continue;
      const int along = rows ? x : y;
      std::vector<Run>& line = runs_[static_cast<std::size_t>(rows ? y : x)];
      if (!line.empty() && line.back().hi == along - 1) {
        line.back().hi = along;
      } else {
        line.push_back({along, along});
      }
    }
  }
  // The lines that hold runs, so that the reads below skip the others.
  line_lo_ = 0;
  while (line_lo_ < across_size_ && runs_[static_cast<std::size_t>(line_lo_)].empty()) ++line_lo_;
  line_hi_ = across_size_ - 1;
  while (line_hi_ >= line_lo_ && runs_[static_cast<std::size_t>(line_hi_)].empty()) --line_hi_;
}

LegBox OwnedRuns::box() const {
  const bool rows = axis_ == BandAxis::kRows;
  int across_lo = std::numeric_limits<int>::max();
  int across_hi = -1;
  int along_lo = std::numeric_limits<int>::max();
  int along_hi = -1;
  for (int c = line_lo_; c <= line_hi_; ++c) {
    const auto& line = runs_[static_cast<std::size_t>(c)];
    if (line.empty()) continue;
    across_lo = std::min(across_lo, c);
    across_hi = c;
    along_lo = std::min(along_lo, line.front().lo);
    along_hi = std::max(along_hi, line.back().hi);
  }
  if (across_hi < 0) return {};
  return rows ? LegBox{along_lo, along_hi, across_lo, across_hi}
              : LegBox{across_lo, across_hi, along_lo, along_hi};
}

namespace {
/// The interval along `line` that `box` covers, when it crosses the line (hi < lo: it does not).
BandExtent covered(const LegBox& box, bool rows, int line) {
  const int across_lo = rows ? box.y_lo : box.x_lo;
  const int across_hi = rows ? box.y_hi : box.x_hi;
  if (line < across_lo || line > across_hi) return {0, -1};
  return rows ? BandExtent{box.x_lo, box.x_hi} : BandExtent{box.y_lo, box.y_hi};
}
}  // namespace

int OwnedRuns::first_kept(int line, std::span<const BandExtent> gaps) const {
  for (const Run& run : runs_[static_cast<std::size_t>(line)]) {
    // Past every removed interval that holds the candidate, until none does.
    int at = run.lo;
    for (bool moved = true; moved && at <= run.hi;) {
      moved = false;
      for (const BandExtent& gap : gaps) {
        if (gap.lo <= at && at <= gap.hi) {
          at = gap.hi + 1;
          moved = true;
        }
      }
    }
    if (at <= run.hi) return at;
  }
  return -1;
}

int OwnedRuns::last_kept(int line, std::span<const BandExtent> gaps) const {
  const auto& runs = runs_[static_cast<std::size_t>(line)];
  for (auto run = runs.rbegin(); run != runs.rend(); ++run) {
    int at = run->hi;
    for (bool moved = true; moved && at >= run->lo;) {
      moved = false;
      for (const BandExtent& gap : gaps) {
        if (gap.lo <= at && at <= gap.hi) {
          at = gap.lo - 1;
          moved = true;
        }
      }
    }
    if (at >= run->lo) return at;
  }
  return -1;
}

RegionBands OwnedRuns::bands(int s, std::span<const int> band_start,
                             std::span<const LegBox> removed) const {
  // Each line's cells kept, once; then, as region_bands: row bands from the grid's bottom, column
  // bands from the first column that keeps a cell (or the band grid's band of it).
  const bool rows = axis_ == BandAxis::kRows;
  kept_.resize(static_cast<std::size_t>(across_size_));
  int first = -1;
  for (int c = line_lo_; c <= line_hi_; ++c) {
    BandExtent& line = kept_[static_cast<std::size_t>(c)];
    const auto& runs = runs_[static_cast<std::size_t>(c)];
    line = {0, -1};
    if (runs.empty()) continue;
    gaps_.clear();
    for (const LegBox& box : removed) {
      const BandExtent gap = covered(box, rows, c);
      if (gap.lo <= gap.hi) gaps_.push_back(gap);
    }
    if (gaps_.empty()) {
      line = {runs.front().lo, runs.back().hi};
    } else {
      line.lo = first_kept(c, gaps_);
      line.hi = line.lo < 0 ? -1 : last_kept(c, gaps_);
    }
    if (line.hi >= 0 && first < 0) first = c;
  }
  RegionBands region;
  region.origin = 0;
  if (!rows) {
    if (first < 0) return {};
    region.origin = band_start.empty() ? first : band_start[static_cast<std::size_t>(first)];
  }
  region.bands.assign(static_cast<std::size_t>((across_size_ - region.origin + s - 1) / s),
                      BandExtent{std::numeric_limits<int>::max(), -1});
  for (int c = std::max(region.origin, first); first >= 0 && c <= line_hi_; ++c) {
    const BandExtent line = kept_[static_cast<std::size_t>(c)];
    if (line.hi < 0) continue;
    BandExtent& e = region.bands[static_cast<std::size_t>((c - region.origin) / s)];
    e.lo = std::min(e.lo, line.lo);
    e.hi = std::max(e.hi, line.hi);
  }
  return region;
}

}  // namespace hullinspect::planners
