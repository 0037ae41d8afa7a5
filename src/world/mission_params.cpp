#include "hullinspect/world/mission_params.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/grid/distance.hpp"

namespace hullinspect::world {

double MissionParams::delta_zeta_cells() const {
  return (s2 - s1) / (2.0 * std::tan(theta_deg * std::numbers::pi / 360.0));
}

int MissionParams::plane_change_steps() const {
  // tan(45°) is not exactly 1 in floating point; without the tolerance Δζ = 1 would need 2 steps.
  const double steps = delta_zeta_cells() / plane_speed_cells;
  return std::max(1, static_cast<int>(std::ceil(steps - 1e-9)));
}

void validate(const MissionParams& p, const HullMask& hull) {
  if (p.uavs < 1) throw ParameterError("uavs", fmt::format("must be at least 1 (got {})", p.uavs));
  if (p.uavs > hull.cell_count()) {
    throw ParameterError("uavs", fmt::format("must be at most the {} hull cells (got {})",
                                             hull.cell_count(), p.uavs));
  }
  if (p.s1 < 1 || p.s1 % 2 == 0) {
    throw ParameterError("s1", fmt::format("must be a positive odd integer (got {})", p.s1));
  }
  if (p.s2 <= p.s1 || p.s2 % 2 == 0) {
    throw ParameterError("s2",
                         fmt::format("must be an odd integer greater than s1 = {} (got {})", p.s1,
                                     p.s2));
  }
  if (p.s2 > 2 * kMaxGridSide + 1) {
    throw ParameterError("s2", fmt::format("must be at most {} (got {})", 2 * kMaxGridSide + 1, p.s2));
  }
  if (!(p.theta_deg > 0.0 && p.theta_deg < 180.0)) {
    throw ParameterError("theta",
                         fmt::format("must be in (0, 180) degrees, exclusive (got {})", p.theta_deg));
  }
  if (!(p.cell_size_m > 0.0)) {
    throw ParameterError("cell_size", fmt::format("must be positive (got {})", p.cell_size_m));
  }
  if (!(p.plane_speed_cells > 0.0)) {
    throw ParameterError("plane_speed",
                         fmt::format("must be positive cells per step (got {})", p.plane_speed_cells));
  }
  if (p.start_z != 1 && p.start_z != 2) {
    throw ParameterError("start_z", fmt::format("must be 1 or 2 (got {})", p.start_z));
  }
  if (p.time_limit < 1) {
    throw ParameterError("time_limit", fmt::format("must be at least 1 step (got {})", p.time_limit));
  }
  if (p.plane_change_steps() > 1000) {
    throw ParameterError("theta", fmt::format("gives a plane change of {} steps; at most 1000 are "
                                              "accepted (raise theta or plane_speed)",
                                              p.plane_change_steps()));
  }
  if (!p.starts.empty() && static_cast<int>(p.starts.size()) != p.uavs) {
    throw ParameterError("starts", fmt::format("gives {} start cells for {} UAVs",
                                               p.starts.size(), p.uavs));
  }
  for (const auto& c : p.starts) {
    if (!hull.mask().contains(c)) {
      throw ParameterError("starts", fmt::format("start cell ({}, {}) is outside the {} × {} grid",
                                                 c.x, c.y, hull.width(), hull.height()));
    }
  }
  if (p.no_fly) {
    if (p.no_fly->width() != hull.width() || p.no_fly->height() != hull.height()) {
      throw ParameterError("no-fly", fmt::format("mask is {} × {} but the hull is {} × {}",
                                                 p.no_fly->width(), p.no_fly->height(),
                                                 hull.width(), hull.height()));
    }
    int allowed_hull = 0;
    for (int i : hull.cells()) allowed_hull += (*p.no_fly)[i] == 0 ? 1 : 0;
    if (allowed_hull < p.uavs) {
      throw ParameterError("no-fly", fmt::format("leaves {} hull cells outside no-fly zones for {} "
                                                 "UAVs to start on",
                                                 allowed_hull, p.uavs));
    }
    for (const auto& c : start_cells(p, hull)) {
      if ((*p.no_fly)[c] != 0) {
        throw ParameterError("starts", fmt::format("start cell ({}, {}) is a no-fly position",
                                                   c.x, c.y));
      }
    }
  }
}

namespace {
// The nearest hull cell to c that is not a no-fly position; ties: lowest y, then lowest x.
grid::Cell snap_allowed(const HullMask& hull, const grid::Grid<std::uint8_t>& no_fly,
                        grid::Cell c) {
  grid::Cell best = hull.snap(c);
  int best_d = grid::kUnreachable;
  for (int i : hull.cells()) {  // (y, x) order, so the first strict minimum wins ties
    if (no_fly[i] != 0) continue;
    const grid::Cell h = hull.mask().cell(i);
    const int d = grid::manhattan(h, c);
    if (d < best_d) {
      best_d = d;
      best = h;
    }
  }
  return best;
}
}  // namespace

std::vector<grid::Cell> start_cells(const MissionParams& p, const HullMask& hull) {
  std::vector<grid::Cell> cells;
  cells.reserve(static_cast<std::size_t>(p.uavs));
  if (!p.starts.empty()) {
    for (const auto& c : p.starts) cells.push_back(hull.snap(c));
    return cells;
  }
  const int a = hull.width();
  const int b = hull.height();
  for (int k = 0; k < p.uavs; ++k) {
    // floor((k + 0.5)·a/n) in integers: (2k + 1)·a / (2n)
    const int x = static_cast<int>((2LL * k + 1) * a / (2LL * p.uavs));
    cells.push_back(p.no_fly ? snap_allowed(hull, *p.no_fly, {x, b / 2}) : hull.snap({x, b / 2}));
  }
  return cells;
}

}  // namespace hullinspect::world
