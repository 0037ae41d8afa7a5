#pragma once
// A UAV's flown trajectory, read from a mission trace, compressed to waypoints (docs/export.md,
// docs/model.md "Frames and exports"): consecutive collinear moves on one plane become one leg;
// plane changes and holds are waypoints of their own with their durations.

#include <nlohmann/json.hpp>

#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "hullinspect/grid/cell.hpp"

namespace hullinspect::io {

/// What the UAV did to arrive at a waypoint.
enum class WaypointAction {
  kStart,        ///< the UAV's position at t = 0
  kMove,         ///< the end of a straight leg on one plane
  kPlaneChange,  ///< arrival on the other plane (the change took `duration` steps)
  kHold,         ///< the end of a hover of `duration` steps
  kTransit,      ///< the end of a plane-2 leg between a launch site and the plan (exports only)
};

/// "start", "move", "plane-change", "hold", "transit".
std::string_view to_string(WaypointAction action);
/// The inverse of to_string; false for any other text.
bool parse_waypoint_action(std::string_view text, WaypointAction& action);

/// A UAV's state in one trace frame.
struct GridState {
  grid::Cell pos;
  int z = 2;
  bool in_transit = false;  ///< between planes (z is then the plane being left)
  bool active = true;
  /// With launch sites (docs/trace-format.md): false on the ground at the site.
  bool airborne = true;
  /// On the ground, or flying between the launch site and the hull (the trace's away_left > 0):
  /// the UAV senses nothing there (docs/model.md §12).
  bool away = false;
};

/// A waypoint on the grid: the UAV is at (cell, z) at time t (seconds = steps) after `duration`
/// steps of `action` (0 for the start).
struct GridWaypoint {
  int t = 0;
  grid::Cell cell;
  int z = 2;
  WaypointAction action = WaypointAction::kStart;
  int duration = 0;
  friend bool operator==(const GridWaypoint&, const GridWaypoint&) = default;
};

/// The states of every UAV in every frame of a validated trace: result[k][t].
std::vector<std::vector<GridState>> trace_states(const nlohmann::json& trace);

/// Two cells one move apart may share a leg only if `same_surface(a, b)` (the stand-off surface
/// is flat between them, e.g. equal depth on a mesh hull). The default accepts every pair.
using SameSurface = std::function<bool(grid::Cell, grid::Cell)>;

/// Compresses one UAV's states (one per time step) into waypoints. The list starts with the
/// t = 0 state and ends at the last frame's time, or at the last frame before the UAV failed.
std::vector<GridWaypoint> compress_trajectory(std::span<const GridState> states,
                                              const SameSurface& same_surface = {});

}  // namespace hullinspect::io
