#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace hullinspect::sim {

/// One take-off to the next landing (docs/model.md, "Batteries and sorties").
struct SortieRecord {
  int takeoff = 0;   ///< t at which the step that takes off starts
  int landing = -1;  ///< t at which the UAV has landed; −1 not landed
  int site = 0;      ///< index of the launch site
};

struct UavCounters {
  int moves = 0;
  int hovers = 0;
  int plane_changes = 0;
  int steps_z1 = 0;  ///< steps ending on plane 1 (not in transit)
  int steps_z2 = 0;
  int steps_transit = 0;  ///< steps spent changing plane
  int failed_at = -1;     ///< step at whose start the UAV failed; −1 never
  int launch_site = -1;   ///< index of the UAV's launch site; −1 without launch sites
  int steps_away = 0;     ///< steps between its site and the hull (ground, take-off, out, home)
  int landed_at = -1;     ///< t at which it had landed at its site at the end; −1 not landed
  int flight_steps = 0;   ///< steps airborne (or taking off or landing) while working
  int swaps = 0;          ///< batteries swapped at a launch site
  bool battery_crash = false;  ///< failed because it was airborne with an empty battery
  /// The least battery left at any t while airborne, in steps; −1 with unlimited flight.
  int min_battery = -1;
  std::vector<SortieRecord> sorties;  ///< every take-off (none without launch sites)
};

/// Counters that planners report (zeros where a planner has no such thing).
struct PlannerStats {
  long long tsp_solves = 0;
  double tsp_seconds = 0;
  double tsp_max_seconds = 0;
  long long tsp_unproven = 0;   ///< TSP solves returned without an optimality proof
  long long tsp_fallbacks = 0;  ///< TSP solves whose solver gave up on its method (a defect)
  long long replans = 0;
  long long assignments = 0;  ///< frontier assignments (Coop-Frontier)
  /// 1 when the mission's partition came from the fallback partitioner because DARP did not
  /// converge (partition/fallback.hpp, docs/model.md); 0 otherwise.
  long long partition_fallbacks = 0;
};

struct MissionResult {
  bool complete = false;      ///< m reached 100 before the time limit
  std::optional<int> t_c;     ///< first t with c(t) = 100; empty if never reached
  std::optional<int> t_m;     ///< first t with m(t) = 100; empty when incomplete
  int steps = 0;              ///< last simulated t
  int failed_uavs = 0;        ///< UAVs that failed during the mission
  bool stopped_idle = false;  ///< ended incomplete because no working UAV had anything left to do
  int bound_t_c = 0;          ///< analytic lower bound on T_c for this instance (model §11)
  int bound_t_m = 0;          ///< analytic lower bound on T_m
  /// Hull cells counted in m(t): those that can reach their final state (all of them without
  /// no-fly zones; docs/model.md).
  int hull_cells = 0;
  int corroded_cells = 0;        ///< #{C = 1} counted in c(t): those a z = 1 footprint can reach
  int unreachable_cells = 0;     ///< hull cells no allowed z = 1 footprint contains
  int unreachable_z2_cells = 0;  ///< hull cells no allowed z = 2 footprint contains
  /// Per t = 0..steps: corroded cells inspected and hull cells known (M ∈ {1, 3}).
  std::vector<int> inspected_series;
  std::vector<int> known_series;
  std::vector<UavCounters> uavs;
  long long observations = 0;            ///< hull-cell readings
  long long redundant_observations = 0;  ///< readings that changed nothing and detected nothing
  long long detections = 0;
  double planner_seconds = 0;  ///< CPU time in the planner (start + decide)
  /// Pairs of UAVs in conflict, summed over the steps (docs/model.md, "Separation"); 0 when the
  /// mission has no separation D.
  long long separation_conflicts = 0;
  /// The smallest max(|Δx|, |Δy|) between two UAVs at any t (0 for an exchange of cells); empty
  /// when the mission has no separation D (nothing is measured) or a single UAV.
  std::optional<int> min_separation;
  /// UAVs that failed because they were airborne with an empty battery (counted in failed_uavs).
  int battery_crashes = 0;
  PlannerStats planner;

  double c_percent(int t) const;  ///< c(t), 100 when there is no corrosion
  double m_percent(int t) const;  ///< m(t)
  UavCounters totals() const;
  /// Take-offs of the whole fleet (0 without launch sites: the UAVs start in the air).
  int sorties() const;
  /// The least battery any UAV had left while airborne, in steps; empty with unlimited flight.
  std::optional<int> min_battery() const;
};

}  // namespace hullinspect::sim
