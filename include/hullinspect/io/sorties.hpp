#pragma once
// Sorties and mission files of an export (docs/export.md "Sorties, launch sites and waypoint
// caps"). A sortie is one take-off to the next landing: from the home point below its launch
// site, up to the site's plane-2 position, along the shortest allowed path to the plan's start,
// the plan, back to the site and down. A sortie with more waypoints than a format's cap is split
// into consecutive parts; each later part starts where the previous one ended.

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/io/ship_frame.hpp"
#include "hullinspect/io/waypoints.hpp"

namespace hullinspect::io {

struct ExportPlan;

/// A waypoint of an export: where on the grid, and the pose there in the ship frame.
struct ExportWaypoint {
  GridWaypoint grid;
  ShipPose pose;
};

/// One take-off to the next landing of the mission the trace records (sim::SortieRecord): the
/// trace's frames [takeoff, landing] are its flight; landing −1 = still airborne at the end.
struct FlownSortie {
  int takeoff = 0;
  int landing = -1;
  int site = 0;  ///< index of the launch site
};

/// One take-off to the next landing of one UAV.
struct Sortie {
  int uav = 0;
  int number = 1;           ///< the UAV's sortie, from 1
  grid::Cell site;          ///< the launch site (grid position)
  bool given_site = false;  ///< false: no --launch, the site is the UAV's start position
  /// True when cut from the mission's sorties (a battery-limited mission): its files are named
  /// per sortie and its waypoints are the trace's flight from take-off to landing.
  bool flown = false;
  ShipPose home;  ///< take-off and landing point: below the site, on its ground
  std::vector<ExportWaypoint> waypoints;  ///< from the site's plane-2 position back to it
  int transit_in = 0;   ///< waypoints[0, transit_in) fly from the site to the plan's start
  int transit_out = 0;  ///< the last transit_out waypoints fly back to the site
  /// waypoints[plan_begin(), plan_end()) are the plan's own: the camera photographs there.
  std::size_t plan_begin() const { return static_cast<std::size_t>(transit_in); }
  std::size_t plan_end() const { return waypoints.size() - static_cast<std::size_t>(transit_out); }
};

/// The sorties of a plan: one per UAV, launched from the nearest of `sites` (Euclidean distance
/// in cells from the UAV's start position; ties go to the site listed first), or from below the
/// UAV's start position when `sites` is empty. Throws ParameterError("launch") for a site outside
/// the grid, on a no-fly position, or on a hull cell that is not on the grid's edge, and when no
/// allowed path joins a site to a UAV's start.
/// A UAV with sorties in `flown` (per UAV; a battery-limited mission lands and takes off again)
/// flies one sortie each instead: the trace's frames from its take-off to its landing at
/// `sites[site]`, compressed as the trace's waypoints (times stay the trace's). Throws
/// ParameterError("launch") when such a sortie names a site `sites` does not have.
/// `home_z`: the ground's height Z (ship frame, m) below every site, where a sortie takes off and
/// lands (unset: the grid's bottom edge); throws ParameterError("launch-height") when it is given
/// and lies above a sortie's first waypoint (the take-off climbs to it).
std::vector<Sortie> plan_sorties(const ExportPlan& plan, const std::vector<grid::Cell>& sites,
                                 const std::vector<std::vector<FlownSortie>>& flown = {},
                                 std::optional<double> home_z = std::nullopt);

/// A UAV's flight compressed to waypoints, its transit marked.
struct Flight {
  std::vector<ExportWaypoint> waypoints;
  int transit_in = 0;   ///< waypoints[0, transit_in) fly from the launch site to the work
  int transit_out = 0;  ///< the last transit_out waypoints fly home from it
};

/// The waypoints of `states`, the trace's frames t0, t0 + 1, …: the frames away from the hull
/// before the first frame at work and after the last (the take-off, the flight out from the launch
/// site, the flight home and the landing, where the UAV senses nothing: GridState::away) are
/// compressed on their own and their moves become `transit`, so the work's waypoints start and end
/// where the work does. The frame the flight home begins in counts as work when the UAV moved into
/// it (the simulator senses there, then turns the UAV home). Without away frames:
/// compress_trajectory's waypoints, no transit.
Flight compress_flight(const ExportPlan& plan, std::span<const GridState> states, int t0);

/// The sorties the trace's airborne flags record per UAV, by sim::SortieRecord's rule: a take-off
/// at the frame before the first one airborne (0 for a UAV airborne at frame 0), the landing at
/// the next frame on the ground (−1 while still airborne at the end), at the UAV's launch site
/// (ExportPlan::site_of). Empty lists for a trace without launch sites.
std::vector<std::vector<FlownSortie>> recorded_sorties(const ExportPlan& plan);

/// The index of the site nearest `start` (the rule of plan_sorties).
std::size_t nearest_site(grid::Cell start, const std::vector<grid::Cell>& sites);

/// A slice of a sortie written as one mission file.
struct MissionPart {
  const Sortie* sortie = nullptr;
  int part = 1;  ///< from 1
  int parts = 1;
  std::span<const ExportWaypoint> waypoints;
  bool takes_off() const { return part == 1; }
  /// The sortie's index of the part's first waypoint.
  std::size_t offset() const {
    return static_cast<std::size_t>(waypoints.data() - sortie->waypoints.data());
  }
  bool lands() const { return part == parts; }
};

/// Splits a sortie into parts of at most `cap` waypoints (0 = no cap); every part after the first
/// starts with the last waypoint of the one before. Throws ParameterError("max-waypoints") when
/// cap is 1 (a part needs the point it starts from and one to fly to).
std::vector<MissionPart> split_sortie(const Sortie& sortie, int cap);

/// The smallest cap split_sortie accepts.
inline constexpr int kMinWaypointCap = 2;

}  // namespace hullinspect::io
