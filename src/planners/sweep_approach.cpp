#include "hullinspect/planners/sweep_approach.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <limits>

namespace hullinspect::planners {

std::vector<grid::Cell> plain_sweep(const grid::Grid<std::int16_t>& owner,
                                    const SweepRequest& request, grid::Cell from) {
  auto waypoints = band_sweep(owner, request.uav, request.band, request.axis, request.trim_ends,
                              from, request.band_start, request.x_lo, request.x_hi);
  if (request.nearer_end && waypoints.size() > 1 &&
      grid::manhattan(from, waypoints.back()) < grid::manhattan(from, waypoints.front()))
    std::reverse(waypoints.begin(), waypoints.end());
  return waypoints;
}

SweepPlan approach_and_sweep(const grid::Grid<std::int16_t>& owner, const SweepRequest& request,
                             grid::Cell from, grid::Grid<std::int16_t>& scratch) {
  // The region's columns: the plans below read only those.
  SweepRequest within = request;
  within.x_lo = owner.width();
  within.x_hi = -1;
  for (int y = 0; y < owner.height(); ++y) {
    for (int x = 0; x < owner.width(); ++x) {
      if (owner(x, y) != request.uav) continue;
      within.x_lo = std::min(within.x_lo, x);
      within.x_hi = std::max(within.x_hi, x);
    }
  }
  SweepPlan best;
  if (within.x_hi < 0) return best;
  if (scratch.width() != owner.width() || scratch.height() != owner.height())
    scratch = grid::Grid<std::int16_t>(owner.width(), owner.height(), -1);
  best.waypoints = plain_sweep(owner, within, from);
  if (best.waypoints.empty()) return best;
  int best_length = flight_length(from, best.waypoints);
  const grid::Cell plain_first = best.waypoints.front();
  const bool rows = request.axis == BandAxis::kRows;
  // "along" runs along a band (y for column bands), "across" from band to band.
  const auto along = [rows](grid::Cell c) { return rows ? c.x : c.y; };
  const auto across = [rows](grid::Cell c) { return rows ? c.y : c.x; };
  const auto cell = [rows](int along_at, int across_at) {
    return rows ? grid::Cell{along_at, across_at} : grid::Cell{across_at, along_at};
  };
  const int across_size = rows ? owner.height() : owner.width();
  const int along_size = rows ? owner.width() : owner.height();
  int along_lo = along_size, along_hi = -1, across_lo = across_size, across_hi = -1;
  for (int y = 0; y < owner.height(); ++y) {
    for (int x = within.x_lo; x <= within.x_hi; ++x) {
      if (owner(x, y) != request.uav) continue;
      const grid::Cell c{x, y};
      along_lo = std::min(along_lo, along(c));
      along_hi = std::max(along_hi, along(c));
      across_lo = std::min(across_lo, across(c));
      across_hi = std::max(across_hi, across(c));
    }
  }
  const int h = (request.band - 1) / 2;
  if (along_lo + h > along_hi - h) return best;  // a region no taller than one footprint
  // The centre line of the band holding an across coordinate (band_sweep's bands).
  const auto centre = [&](int a) {
    int band_first = across_lo + (a - across_lo) / request.band * request.band;
    if (!rows && !request.band_start.empty())
      band_first = request.band_start[static_cast<std::size_t>(a)];
    return std::min(band_first + h, across_size - 1);
  };
  const int from_along = along(from);
  const int from_across = across(from);
  const std::array<int, 2> edges{along_lo + h, along_hi - h};
  const std::array<int, 2> lines{from_across,
                                 centre(std::clamp(from_across, across_lo, across_hi))};
  for (const int line : lines) {
    for (const int edge : edges) {
      for (const int target : {line, across(plain_first)}) {
        // from → (line, from_along) → (line, edge) → (target, edge), each leg straight.
        const std::array<grid::Cell, 4> path{from, cell(from_along, line), cell(edge, line),
                                             cell(edge, target)};
        // Only the region's columns of the scratch grid are read (as band_sweep is told).
        for (int y = 0; y < owner.height(); ++y) {
          for (int x = within.x_lo; x <= within.x_hi; ++x) scratch(x, y) = owner(x, y);
        }
        int length = 0;
        for (std::size_t leg = 1; leg < path.size(); ++leg) {
          const grid::Cell a = path[leg - 1];
          const grid::Cell b = path[leg];
          length += grid::manhattan(a, b);
          const int x_lo = std::max(0, std::min(a.x, b.x) - h);
          const int x_hi = std::min(owner.width() - 1, std::max(a.x, b.x) + h);
          const int y_lo = std::max(0, std::min(a.y, b.y) - h);
          const int y_hi = std::min(owner.height() - 1, std::max(a.y, b.y) + h);
          for (int y = y_lo; y <= y_hi; ++y) {
            for (int x = x_lo; x <= x_hi; ++x) {
              if (scratch(x, y) == request.uav) scratch(x, y) = -1;
            }
          }
        }
        auto sweep = plain_sweep(scratch, within, path.back());
        length += flight_length(path.back(), sweep);
        if (length >= best_length) continue;
        best_length = length;
        best.waypoints.clear();
        for (std::size_t i = 1; i < path.size(); ++i) {
          if (path[i] != path[i - 1] &&
              (best.waypoints.empty() || best.waypoints.back() != path[i]))
            best.waypoints.push_back(path[i]);
        }
        best.approach = best.waypoints.size();
        best.waypoints.insert(best.waypoints.end(), sweep.begin(), sweep.end());
      }
    }
  }
  return best;
}

}  // namespace hullinspect::planners
