#pragma once
// Mission parameters (model.md §1): fleet, camera footprints, plane-change time, start cells, time
// limit.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::world {

/// The half-side h of a square footprint of odd side s = 2h + 1: a position's footprint holds the
/// cells within Chebyshev distance h of it. The one place a side becomes a half-side.
constexpr int footprint_half(int side) {
  return (side - 1) / 2;
}

/// The largest footprint side validate() accepts (s2; s1 < s2): one whose half-side spans the
/// largest grid.
inline constexpr int kMaxFootprintSide = 2 * kMaxGridSide + 1;

/// The speeds (--speed, --climb-speed) validate() accepts, m/s.
inline constexpr double kMinSpeedMs = 1e-3;
inline constexpr double kMaxSpeedMs = 1e3;

struct MissionParams {
  int uavs = 4;                    ///< n, fleet size (>= 1, <= hull cells)
  int s1 = 5;                      ///< footprint side at z = 1 (close-up), odd, cells
  int s2 = 7;                      ///< footprint side at z = 2 (detection), odd, > s1, cells
  double theta_deg = 90.0;         ///< camera aperture θ, degrees, in (0, 180)
  double cell_size_m = 0.5;        ///< side of one cell in metres (for reports and exports)
  double plane_speed_cells = 1.0;  ///< standoff change per step, cells per step (> 0)
  /// Horizontal speed in m/s (docs/model.md, "Speed and time"): one move takes cell / speed
  /// seconds. Empty = one cell per second, the paper's model.
  std::optional<double> speed_m_s;
  /// Climb speed in m/s for plane changes and the take-off. Empty = plane_speed_cells cells per
  /// second (with the default speed, u_z steps as in the paper).
  std::optional<double> climb_speed_m_s;
  int start_z = 2;                 ///< plane every UAV starts on (1 or 2)
  std::vector<grid::Cell> starts;  ///< explicit start cells; empty = model.md §1 default spacing
  int time_limit = 20000;          ///< steps after which an unfinished mission is "incomplete"
  /// Launch sites (docs/model.md, "Launch sites"): the UAVs start on the ground at a site and end
  /// the mission landed at it. Empty = the paper's model (start airborne at the start cells).
  std::vector<grid::Cell> launch_sites;
  double launch_transfer_s = 0;          ///< seconds each way between a site and the quay beyond
  std::optional<double> takeoff_time_s;  ///< seconds from the ground to plane 2; default u_z steps
  /// D (model.md, "Separation"): two UAVs conflict at a step when max(|Δx|, |Δy|) < D, whatever
  /// their planes, or when they exchange cells while D >= 1. 0 = the paper's model (no check).
  int separation = 0;
  bool strict_separation = false;  ///< a conflict is a mission error instead of a count
  /// With D > 0, the deconfliction layer (sim/deconfliction.hpp) adjusts the planner's actions so
  /// that no conflict happens; false hands them to the simulator as they are (conflicts counted).
  bool deconflict = true;
  /// Batteries (docs/model.md, "Batteries and sorties"): seconds of flight per battery; empty =
  /// unlimited, the paper's model. Needs at least one launch site, where batteries are swapped.
  std::optional<double> endurance_s;
  std::optional<double> reserve_s;  ///< seconds left on landing; default 10 % of the endurance
  double swap_time_s = 120;         ///< seconds on the ground at a site to swap a battery
  /// No-fly positions (1 = no UAV may be there, on either plane), the hull's size; null = none.
  std::shared_ptr<const grid::Grid<std::uint8_t>> no_fly;

  /// Δζ = (s2 − s1) / (2·tan(θ/2)), in cells.
  double delta_zeta_cells() const;
  /// u_z = ceil(Δζ / v_z) steps, v_z the climb speed in cells per step (1, 2, 3 for s2 = 7, 9, 11
  /// with s1 = 5, θ = 90° and the default speeds).
  int plane_change_steps() const;
  /// The duration of one step in seconds: cell_size_m / speed (exactly 1 without --speed). Every
  /// time a user sees is steps × step_seconds().
  double step_seconds() const;
  /// Whole steps that `seconds` of mission time take, rounded up (a decimal's binary error, like
  /// 3.0000000001 steps, stays 3).
  int steps_for_seconds(double seconds) const;
  /// `steps` × step_seconds(), rounded to the microsecond so that 3 steps of 0.1 s print as 0.3
  /// (exactly `steps` without --speed).
  double seconds(long long steps) const;
  /// Footprint side on plane z.
  int footprint(int z) const { return z == 1 ? s1 : s2; }
  /// Half-side of the footprint on plane z (footprint_half(footprint(z))).
  int half_side(int z) const { return footprint_half(footprint(z)); }
};

/// The most UAVs the separation D leaves room for on a w × h grid: ceil(w/D)·ceil(h/D) (positions
/// pairwise at least D apart in Chebyshev distance); unlimited (INT_MAX) for D <= 1.
long long separation_capacity(int separation, int width, int height);

/// Throws ParameterError naming the field ("uavs", "s2", "theta", …) and the accepted range, for
/// every check that needs no start cells; once it passes, start_cells(params, hull) is bounded.
void validate_without_starts(const MissionParams& params, const HullMask& hull);
/// The checks of the start cells (no-fly positions, two UAVs on one cell, separation, the battery's
/// reach) for `starts` = start_cells(params, hull). Call after validate_without_starts().
void validate_starts(const MissionParams& params, const HullMask& hull,
                     std::span<const grid::Cell> starts);
/// Both, computing the start cells once; returns them so that the mission can use them.
std::vector<grid::Cell> validate(const MissionParams& params, const HullMask& hull);

/// The start cells of the mission: `params.starts` snapped to the hull, or the defaults of
/// docs/model.md §1: UAV k aims at x = x0 + floor((k + 0.5)·w/n) on the middle row of the hull's
/// bounding box and takes the nearest hull cell that no earlier UAV took and that is not a no-fly
/// position, so default starts are always distinct and allowed.
std::vector<grid::Cell> start_cells(const MissionParams& params, const HullMask& hull);

}  // namespace hullinspect::world
