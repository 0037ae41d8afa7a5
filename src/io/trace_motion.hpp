#pragma once
// The flown mission's rules over a trace's frames (docs/trace-format.md, "Rules"): the motion rules
// of sim/uav_rules.hpp for every UAV of every frame, no-fly positions, and for a mission with
// launch sites the ground, the battery and its swaps, with the counts the result must agree with.

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/grid/flight_steps.hpp"
#include "trace_checker.hpp"

namespace hullinspect::io::detail {

/// What the rules need from a trace's top-level fields.
struct TraceMission {
  int width = 1;
  int height = 1;
  int plane_change_steps = 1;
  std::size_t fields = 5;  ///< values per UAV in a frame's `u` (the length of `uav_fields`)
  std::size_t uavs = 0;
  const nlohmann::json* no_fly = nullptr;  ///< the `no_fly` rows, or null
  /// A version 2 trace of a mission with launch sites: it does not record when a UAV is away.
  bool away_unrecorded = false;
  /// Version 3: a UAV sent home from plane 1 is recorded on plane 1 until its first move away.
  bool climb_recorded_at_move = false;
  grid::FlightSteps flights;
  std::vector<grid::Cell> sites;  ///< empty: the paper's model (no launch site)
  std::vector<int> site_of;       ///< per UAV, an index into sites
  bool battery = false;
  int endurance = 0;  ///< steps (with a battery)
  int reserve = 0;
  int swap = 0;
  int separation = 0;  ///< D in cells, 0 when not measured

  bool physical() const { return fields == 8; }
};

/// Reads and checks `uav_fields`, `launch`, `battery` and `separation` (and the frames' first `u`
/// for the fleet's size) of a trace whose grid, footprint, ship frame and no-fly rows are checked.
TraceMission trace_mission(const TraceChecker& check, const nlohmann::json& trace, int version,
                           int width, int height, int plane_change_steps);

/// Bounds of each value of a UAV in `u`, [lo, hi], in the order of `uav_fields`.
std::vector<std::pair<std::int64_t, std::int64_t>> uav_value_bounds(const TraceMission& mission);

/// What the frames hold, for the result to agree with and for the safety rules.
struct TraceCounts {
  long long battery_crashes = 0;
  long long sorties = 0;       ///< take-offs
  long long flight_steps = 0;  ///< UAV-steps airborne at either end, not failed
  long long separation_conflicts = 0;
  std::optional<int> min_separation;  ///< with D and two UAVs or more
  // The first breach of each safety rule ("frames[t].u: …"), empty when none.
  std::string first_crash;
  std::string first_low_landing;
  std::string first_conflict;
};

/// Checks every frame (already checked one by one) against the rules; throws at the first breach.
TraceCounts check_motion(const TraceChecker& check, const nlohmann::json& frames,
                         const TraceMission& mission);

/// Checks that the result's battery_crashes, sorties, flight_steps, separation_conflicts and
/// min_separation (those the mission records) are what the frames hold.
void check_counts(const TraceChecker& check, const nlohmann::json& result,
                  const TraceMission& mission, const TraceCounts& counts);

}  // namespace hullinspect::io::detail
