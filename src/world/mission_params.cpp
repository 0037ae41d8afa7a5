#include "hullinspect/world/mission_params.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/plural.hpp"
#include "hullinspect/grid/distance.hpp"
#include "hullinspect/world/battery.hpp"
#include "hullinspect/world/launch_sites.hpp"

namespace hullinspect::world {

namespace {
// The longest plane change (steps between z = 1 and z = 2) validate() accepts.
constexpr int kMaxPlaneChangeSteps = 1000;
}  // namespace

double MissionParams::delta_zeta_cells() const {
  return (s2 - s1) / (2.0 * std::tan(theta_deg * std::numbers::pi / 360.0));
}

double MissionParams::step_seconds() const {
  return speed_m_s ? cell_size_m / *speed_m_s : 1.0;
}

double MissionParams::seconds(long long steps) const {
  if (!speed_m_s) return static_cast<double>(steps);
  return std::round(static_cast<double>(steps) * step_seconds() * 1e6) / 1e6;
}

int MissionParams::steps_for_seconds(double seconds) const {
  return static_cast<int>(std::ceil(seconds / step_seconds() - 1e-9));
}

int MissionParams::plane_change_steps() const {
  // The climb speed in cells per step: plane_speed_cells itself in the paper's model (so that its
  // u_z is computed exactly as before); otherwise metres per second times the step's seconds.
  double cells_per_step = plane_speed_cells;
  if (speed_m_s || climb_speed_m_s) {
    const double climb_m_s = climb_speed_m_s.value_or(plane_speed_cells * cell_size_m);
    cells_per_step = climb_m_s * step_seconds() / cell_size_m;
  }
  // tan(45°) is not exactly 1 in floating point; without the tolerance Δζ = 1 would need 2 steps.
  // validate() refuses parameters whose plane change exceeds kMaxPlaneChangeSteps before this is
  // used; the clamp keeps the conversion defined even for θ = 1e-300 (Δζ ≈ 1e300 cells).
  const double steps = std::ceil(delta_zeta_cells() / cells_per_step - 1e-9);
  if (!(steps < kMaxPlaneChangeSteps + 1.0)) return kMaxPlaneChangeSteps + 1;
  return std::max(1, static_cast<int>(steps));
}

long long separation_capacity(int separation, int width, int height) {
  if (separation <= 1) return std::numeric_limits<int>::max();
  const long long d = separation;
  return ((width + d - 1) / d) * ((height + d - 1) / d);
}

namespace {

// D against the grid: room for n UAVs pairwise D apart.
void validate_separation_room(const MissionParams& p, const HullMask& hull) {
  if (p.separation < 0) {
    throw ParameterError(
        "separation", fmt::format("must be a whole number of cells >= 0 (got {})", p.separation));
  }
  if (p.separation == 0) return;
  const long long room = separation_capacity(p.separation, hull.width(), hull.height());
  if (p.uavs > room) {
    throw ParameterError(
        "separation",
        fmt::format("{} cells leaves room for at most {} on the {} × {} grid (got {})",
                    p.separation, plural(room, "UAV"), hull.width(), hull.height(),
                    plural(p.uavs, "UAV")));
  }
}

// D against the start cells: pairwise D apart (a conflict at t = 0 is one no layer can undo).
void validate_separation_starts(const MissionParams& p, std::span<const grid::Cell> starts) {
  if (p.separation == 0) return;
  for (std::size_t a = 0; a < starts.size(); ++a) {
    for (std::size_t b = a + 1; b < starts.size(); ++b) {
      const int d = grid::chebyshev(starts[a], starts[b]);
      if (d < p.separation) {
        throw ParameterError(
            "separation",
            fmt::format("{} cells: UAVs {} and {} start {} apart, at ({}, {}) and ({}, {}) (give "
                        "--start cells at least {} apart, or fewer UAVs)",
                        p.separation, a, b, plural(d, "cell"), starts[a].x, starts[a].y,
                        starts[b].x, starts[b].y, p.separation));
      }
    }
  }
}

}  // namespace

void validate_without_starts(const MissionParams& p, const HullMask& hull) {
  if (p.uavs < 1) throw ParameterError("uavs", fmt::format("must be at least 1 (got {})", p.uavs));
  if (p.uavs > hull.cell_count()) {
    throw ParameterError("uavs", fmt::format("must be at most the {} hull cells (got {})",
                                             hull.cell_count(), p.uavs));
  }
  if (p.s1 < 1 || p.s1 % 2 == 0) {
    throw ParameterError("s1", fmt::format("must be a positive odd integer (got {})", p.s1));
  }
  if (p.s2 <= p.s1 || p.s2 % 2 == 0) {
    throw ParameterError(
        "s2", fmt::format("must be an odd integer greater than s1 = {} (got {})", p.s1, p.s2));
  }
  if (p.s2 > kMaxFootprintSide) {
    throw ParameterError("s2", fmt::format("must be at most {} (got {})", kMaxFootprintSide, p.s2));
  }
  if (!(p.theta_deg > 0.0 && p.theta_deg < 180.0)) {
    throw ParameterError(
        "theta", fmt::format("must be in (0, 180) degrees, exclusive (got {})", p.theta_deg));
  }
  if (!(p.cell_size_m > 0.0 && p.cell_size_m <= 1e6)) {
    throw ParameterError("cell_size",
                         fmt::format("must be in (0, 1e6] metres (got {})", p.cell_size_m));
  }
  if (!(p.plane_speed_cells > 0.0 && p.plane_speed_cells <= 1e6)) {
    throw ParameterError("plane_speed", fmt::format("must be in (0, 1e6] cells per step (got {})",
                                                    p.plane_speed_cells));
  }
  // Speeds: positive and finite; bounded so that a step lasts between a microsecond and a day for
  // any cell size validate() accepts.
  for (const auto& [name, value] :
       {std::pair{"speed", p.speed_m_s}, std::pair{"climb-speed", p.climb_speed_m_s}}) {
    if (value && !(*value >= kMinSpeedMs && *value <= kMaxSpeedMs)) {
      throw ParameterError(name, fmt::format("must be a speed in [{}, {}] m/s (got {})",
                                             kMinSpeedMs, kMaxSpeedMs, *value));
    }
  }
  if (p.start_z != 1 && p.start_z != 2) {
    throw ParameterError("start_z", fmt::format("must be 1 or 2 (got {})", p.start_z));
  }
  if (p.time_limit < 1) {
    throw ParameterError("time_limit",
                         fmt::format("must be at least 1 step (got {})", p.time_limit));
  }
  if (p.plane_change_steps() > kMaxPlaneChangeSteps) {
    // Blame s2 when even the default aperture (90°) cannot make the change short enough.
    MissionParams at_90 = p;
    at_90.theta_deg = 90.0;
    const double cells = p.delta_zeta_cells();
    if (at_90.plane_change_steps() > kMaxPlaneChangeSteps) {
      throw ParameterError(
          "s2",
          fmt::format("with s1 = {} and theta = {}° puts the planes {:.3g} cells apart, a plane "
                      "change of more than {} steps (lower s2)",
                      p.s1, p.theta_deg, cells, kMaxPlaneChangeSteps));
    }
    throw ParameterError(
        "theta", fmt::format("{}° with s1 = {} and s2 = {} puts the planes {:.3g} cells apart, a "
                             "plane change of more than {} steps (widen theta)",
                             p.theta_deg, p.s1, p.s2, cells, kMaxPlaneChangeSteps));
  }
  if (!p.starts.empty() && static_cast<int>(p.starts.size()) != p.uavs) {
    throw ParameterError("starts",
                         fmt::format("gives {} for {}",
                                     plural(static_cast<long long>(p.starts.size()), "start cell"),
                                     plural(p.uavs, "UAV")));
  }
  for (const auto& c : p.starts) {
    if (!hull.mask().contains(c)) {
      throw ParameterError("starts", fmt::format("start cell ({}, {}) is outside the {} × {} grid",
                                                 c.x, c.y, hull.width(), hull.height()));
    }
  }
  if (p.no_fly) {
    if (p.no_fly->width() != hull.width() || p.no_fly->height() != hull.height()) {
      throw ParameterError("no-fly",
                           fmt::format("mask is {} × {} but the hull is {} × {}", p.no_fly->width(),
                                       p.no_fly->height(), hull.width(), hull.height()));
    }
    int allowed_hull = 0;
    for (int i : hull.cells()) allowed_hull += (*p.no_fly)[i] == 0 ? 1 : 0;
    if (allowed_hull < p.uavs) {
      throw ParameterError("no-fly",
                           fmt::format("leaves {} outside no-fly zones for {} to start on",
                                       plural(allowed_hull, "hull cell"), plural(p.uavs, "UAV")));
    }
  }
  validate_launch_sites(p, hull);
  validate_separation_room(p, hull);
  validate_battery(p);
}

void validate_starts(const MissionParams& p, const HullMask& hull,
                     std::span<const grid::Cell> starts) {
  if (p.no_fly) {
    for (const auto& c : starts) {
      if ((*p.no_fly)[c] != 0) {
        throw ParameterError("starts",
                             fmt::format("start cell ({}, {}) is a no-fly position", c.x, c.y));
      }
    }
  }
  // Explicit starts that snap onto one hull cell: refused here, before any planning starts.
  if (!p.starts.empty()) {
    grid::Grid<int> first(hull.width(), hull.height(), -1);
    for (std::size_t k = 0; k < starts.size(); ++k) {
      int& owner = first(starts[k].x, starts[k].y);
      if (owner >= 0) {
        const auto other = static_cast<std::size_t>(owner);
        throw ParameterError(
            "starts", fmt::format("UAVs {} and {} both start on cell ({}, {}) (given ({}, {}) and "
                                  "({}, {}); cells off the hull snap to the nearest hull cell); "
                                  "every UAV needs its own start cell",
                                  other, k, starts[k].x, starts[k].y, p.starts[other].x,
                                  p.starts[other].y, p.starts[k].x, p.starts[k].y));
      }
      owner = static_cast<int>(k);
    }
  }
  validate_separation_starts(p, starts);
  validate_battery_reach(p, hull, starts);
}

std::vector<grid::Cell> validate(const MissionParams& p, const HullMask& hull) {
  validate_without_starts(p, hull);
  auto starts = start_cells(p, hull);
  validate_starts(p, hull, starts);
  return starts;
}

std::vector<grid::Cell> start_cells(const MissionParams& p, const HullMask& hull) {
  std::vector<grid::Cell> cells;
  cells.reserve(static_cast<std::size_t>(p.uavs));
  if (!p.starts.empty()) {
    for (const auto& c : p.starts) cells.push_back(hull.snap(c));
    return cells;
  }
  // Spread along the hull's own extent (its bounding box, not the grid's): UAV k aims at
  // x = x0 + floor((k + 0.5)·w/n) on the box's middle row and takes the nearest hull cell that no
  // earlier UAV took (Manhattan distance, ties to the lowest (y, x)), so the n starts are distinct
  // for every n up to the number of hull cells.
  int x0 = hull.width();
  int x1 = -1;
  int y0 = hull.height();
  int y1 = -1;
  for (const int i : hull.cells()) {
    const grid::Cell c = hull.mask().cell(i);
    x0 = std::min(x0, c.x);
    x1 = std::max(x1, c.x);
    y0 = std::min(y0, c.y);
    y1 = std::max(y1, c.y);
  }
  const long long w = x1 - x0 + 1;
  grid::Grid<std::uint8_t> taken(hull.width(), hull.height(), 0);
  for (int k = 0; k < p.uavs; ++k) {
    const grid::Cell aim{x0 + static_cast<int>((2LL * k + 1) * w / (2LL * p.uavs)),
                         y0 + (y1 - y0 + 1) / 2};
    // Never a cell another UAV took, nor a no-fly position; with a separation D, nor a cell
    // closer than D to an earlier UAV's start (so that no conflict exists at t = 0).
    auto free = [&](int i) {
      if (taken[i] != 0 || (p.no_fly && (*p.no_fly)[i] != 0)) return false;
      if (p.separation <= 1) return true;
      const grid::Cell c = hull.mask().cell(i);
      return std::none_of(cells.begin(), cells.end(),
                          [&](grid::Cell o) { return grid::chebyshev(c, o) < p.separation; });
    };
    grid::Cell best = hull.snap(aim);
    if (!free(hull.mask().index(best))) {
      int best_d = std::numeric_limits<int>::max();
      for (const int i : hull.cells()) {  // (y, x) order: the first strict minimum wins ties
        const grid::Cell h = hull.mask().cell(i);
        const int d = grid::manhattan(h, aim);
        if (free(i) && d < best_d) {
          best_d = d;
          best = h;
        }
      }
    }
    taken(best.x, best.y) = 1;
    cells.push_back(best);
  }
  return cells;
}

}  // namespace hullinspect::world
