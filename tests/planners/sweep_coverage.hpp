#pragma once
// What a flight through waypoints sees, the fleets they start and a ragged region: shared by the
// tests of band_sweep, band_partition, sweep_approach and sweep_chooser.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "hullinspect/grid/grid.hpp"

namespace hullinspect::planners::sweep_coverage {

/// Cells of `owner == uav` that no position of the flown bands sees (footprint half-width h): a
/// band is a pair of consecutive waypoints on one line; a one-waypoint band is a point.
inline int unseen_cells(const grid::Grid<std::int16_t>& owner, int uav, int h, grid::Cell from,
                        const std::vector<grid::Cell>& waypoints) {
  grid::Grid<std::uint8_t> seen(owner.width(), owner.height(), 0);
  const auto see = [&](grid::Cell p) {
    for (int y = std::max(0, p.y - h); y <= std::min(owner.height() - 1, p.y + h); ++y)
      for (int x = std::max(0, p.x - h); x <= std::min(owner.width() - 1, p.x + h); ++x)
        seen(x, y) = 1;
  };
  // Every position of the flight: straight legs between consecutive points, x then y.
  grid::Cell at = from;
  for (const grid::Cell w : waypoints) {
    while (at != w) {
      see(at);
      if (at.x != w.x) {
        at.x += w.x > at.x ? 1 : -1;
      } else {
        at.y += w.y > at.y ? 1 : -1;
      }
    }
    see(at);
  }
  int unseen = 0;
  for (int y = 0; y < owner.height(); ++y)
    for (int x = 0; x < owner.width(); ++x) unseen += owner(x, y) == uav && seen(x, y) == 0;
  return unseen;
}

/// n start cells spread along a hull `width` wide, at row y: x = (2k + 1)·width / (2n), the
/// default starts' spacing.
inline std::vector<grid::Cell> spread_starts(int width, int n, int y = 15) {
  std::vector<grid::Cell> starts;
  for (int k = 0; k < n; ++k) starts.push_back({(2 * k + 1) * width / (2 * n), y});
  return starts;
}

/// A ragged region of UAV 0 on a 40 × 30 grid: columns 0-19 hold rows 0-9 only, columns 20-39
/// all 30 rows (a share left part-swept has such steps).
inline grid::Grid<std::int16_t> ragged_region() {
  grid::Grid<std::int16_t> owner(40, 30, -1);
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 40; ++x) {
      if (x >= 20 || y < 10) owner(x, y) = 0;
    }
  }
  return owner;
}

}  // namespace hullinspect::planners::sweep_coverage
