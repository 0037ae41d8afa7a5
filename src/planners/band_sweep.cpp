#include "hullinspect/planners/band_sweep.hpp"

#include <algorithm>
#include <limits>

#include "hullinspect/world/mission_params.hpp"

namespace hullinspect::planners {

RegionBands region_bands(const grid::Grid<std::int16_t>& owner, int uav, int s, BandAxis axis,
                         std::span<const int> band_start, int x_lo, int x_hi) {
  // Only columns [x_lo, x_hi] are looked at (a caller that knows the region's columns saves the
  // scan of the rest).
  x_lo = std::max(0, x_lo);
  x_hi = x_hi < 0 ? owner.width() - 1 : std::min(owner.width() - 1, x_hi);
  const bool rows = axis == BandAxis::kRows;
  const int across_size = rows ? owner.height() : owner.width();
  // "along" runs along a band (x for row bands), "across" from band to band.
  const auto along = [rows](int x, int y) { return rows ? x : y; };
  const auto across = [rows](int x, int y) { return rows ? y : x; };
  // Row bands start at the grid's bottom (as the lawnmower's strips); column bands at the
  // region's leftmost column, so a region w columns wide needs ceil(w / s) of them, or on the
  // band grid given (a region of the band partition).
  RegionBands region;
  region.origin = rows ? 0 : std::numeric_limits<int>::max();
  if (!rows) {
    for (int y = 0; y < owner.height(); ++y) {
      for (int x = x_lo; x <= x_hi; ++x) {
        if (owner(x, y) == uav) region.origin = std::min(region.origin, x);
      }
    }
    if (region.origin == std::numeric_limits<int>::max()) return {};
    if (!band_start.empty()) region.origin = band_start[static_cast<std::size_t>(region.origin)];
  }
  region.bands.assign(static_cast<std::size_t>((across_size - region.origin + s - 1) / s),
                      BandExtent{std::numeric_limits<int>::max(), -1});
  for (int y = 0; y < owner.height(); ++y) {
    for (int x = x_lo; x <= x_hi; ++x) {
      if (owner(x, y) != uav) continue;
      BandExtent& e = region.bands[static_cast<std::size_t>((across(x, y) - region.origin) / s)];
      e.lo = std::min(e.lo, along(x, y));
      e.hi = std::max(e.hi, along(x, y));
    }
  }
  return region;
}

std::vector<grid::Cell> sweep_bands(const RegionBands& region, int s, BandAxis axis, bool trim_ends,
                                    grid::Cell from, int across_size) {
  const bool rows = axis == BandAxis::kRows;
  const int h = world::footprint_half(s);
  const auto cell = [rows](int along_at, int across_at) {
    return rows ? grid::Cell{along_at, across_at} : grid::Cell{across_at, along_at};
  };
  std::vector<grid::Cell> waypoints;
  grid::Cell at = from;
  for (std::size_t j = 0; j < region.bands.size(); ++j) {
    const BandExtent& e = region.bands[j];
    if (e.hi < 0) continue;
    // The footprint of a position on the centre line holds the whole band's width.
    const int centre = std::min(region.origin + static_cast<int>(j) * s + h, across_size - 1);
    int lo = e.lo;
    int hi = e.hi;
    if (trim_ends) {
      // Its footprint reaches h cells beyond the position along the band as well.
      lo = e.lo + h <= e.hi - h ? e.lo + h : (e.lo + e.hi) / 2;
      hi = e.lo + h <= e.hi - h ? e.hi - h : lo;
    }
    grid::Cell first = cell(lo, centre);
    grid::Cell last = cell(hi, centre);
    if (grid::manhattan(at, last) < grid::manhattan(at, first)) std::swap(first, last);
    waypoints.push_back(first);
    if (last != first) waypoints.push_back(last);
    at = last;
  }
  return waypoints;
}

std::vector<grid::Cell> band_sweep(const grid::Grid<std::int16_t>& owner, int uav, int s,
                                   BandAxis axis, bool trim_ends, grid::Cell from,
                                   std::span<const int> band_start, int x_lo, int x_hi) {
  const int across_size = axis == BandAxis::kRows ? owner.height() : owner.width();
  return sweep_bands(region_bands(owner, uav, s, axis, band_start, x_lo, x_hi), s, axis, trim_ends,
                     from, across_size);
}

LegBox leg_footprints(grid::Cell a, grid::Cell b, int half, int width, int height) {
  return {std::max(0, std::min(a.x, b.x) - half), std::min(width - 1, std::max(a.x, b.x) + half),
          std::max(0, std::min(a.y, b.y) - half), std::min(height - 1, std::max(a.y, b.y) + half)};
}

int flight_length(grid::Cell from, const std::vector<grid::Cell>& waypoints) {
  int length = 0;
  for (const grid::Cell w : waypoints) {
    length += grid::manhattan(from, w);
    from = w;
  }
  return length;
}

}  // namespace hullinspect::planners
