#pragma once
// Mission parameters (model.md §1): fleet, camera footprints, plane-change time, start cells, time
// limit.

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::world {

struct MissionParams {
  int uavs = 4;                    ///< n, fleet size (>= 1, <= hull cells)
  int s1 = 5;                      ///< footprint side at z = 1 (close-up), odd, cells
  int s2 = 7;                      ///< footprint side at z = 2 (detection), odd, > s1, cells
  double theta_deg = 90.0;         ///< camera aperture θ, degrees, in (0, 180)
  double cell_size_m = 0.5;        ///< side of one cell in metres (for reports and exports)
  double plane_speed_cells = 1.0;  ///< standoff change per step, cells per step (> 0)
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
  /// u_z = ceil(Δζ / plane_speed_cells) steps (1, 2, 3 for s2 = 7, 9, 11 with s1 = 5, θ = 90°).
  int plane_change_steps() const;
  /// Footprint side on plane z.
  int footprint(int z) const { return z == 1 ? s1 : s2; }
};

/// The most UAVs the separation D leaves room for on a w × h grid: ceil(w/D)·ceil(h/D) (positions
/// pairwise at least D apart in Chebyshev distance); unlimited (INT_MAX) for D <= 1.
long long separation_capacity(int separation, int width, int height);

/// Throws ParameterError naming the field ("uavs", "s2", "theta", …) and the accepted range.
void validate(const MissionParams& params, const HullMask& hull);

/// The start cells of the mission: `params.starts` snapped to the hull, or the defaults of
/// docs/model.md §1: UAV k aims at x = x0 + floor((k + 0.5)·w/n) on the middle row of the hull's
/// bounding box and takes the nearest hull cell that no earlier UAV took and that is not a no-fly
/// position, so default starts are always distinct and allowed.
std::vector<grid::Cell> start_cells(const MissionParams& params, const HullMask& hull);

}  // namespace hullinspect::world
