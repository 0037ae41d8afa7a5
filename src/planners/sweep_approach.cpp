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
  // The region's extent, in one scan; the plans below read only its columns.
  int x_lo = owner.width(), x_hi = -1, y_lo = owner.height(), y_hi = -1;
  for (int y = 0; y < owner.height(); ++y) {
    for (int x = 0; x < owner.width(); ++x) {
      if (owner(x, y) != request.uav) continue;
      x_lo = std::min(x_lo, x);
      x_hi = std::max(x_hi, x);
      y_lo = std::min(y_lo, y);
      y_hi = std::max(y_hi, y);
    }
  }
  SweepPlan best;
  if (x_hi < 0) return best;
  SweepRequest within = request;
  within.x_lo = x_lo;
  within.x_hi = x_hi;
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
  const int along_lo = rows ? x_lo : y_lo;
  const int along_hi = rows ? x_hi : y_hi;
  const int across_lo = rows ? y_lo : x_lo;
  const int across_hi = rows ? y_hi : x_hi;
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
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const int line = lines[l];
    if (l > 0 && line == lines[0]) continue;  // on a band's centre line already
    for (const int edge : edges) {
      const std::array<int, 2> targets{line, across(plain_first)};
      for (std::size_t t = 0; t < targets.size(); ++t) {
        const int target = targets[t];
        if (t > 0 && target == targets[0]) continue;  // the plain sweep starts on this line
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
          const LegBox box = leg_footprints(a, b, h, owner.width(), owner.height());
          for (int y = box.y_lo; y <= box.y_hi; ++y) {
            for (int x = box.x_lo; x <= box.x_hi; ++x) {
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
