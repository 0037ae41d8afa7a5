#include "hullinspect/io/result_json.hpp"

#include <fmt/format.h>

#include <cmath>

#include "hullinspect/world/battery.hpp"

namespace hullinspect::io {

using nlohmann::json;

json seconds_json(const world::MissionParams& params, const std::optional<int>& steps) {
  if (!steps) return json(nullptr);
  const double s = params.seconds(*steps);
  if (s == std::floor(s) && std::abs(s) < 9e15) return json(static_cast<long long>(s));
  return json(s);
}

std::string seconds_text(const world::MissionParams& params, const std::optional<int>& steps) {
  return steps ? fmt::format("{} s", params.seconds(*steps)) : std::string("—");
}

namespace {
/// time / bound to three decimals; null when the time was not reached or the bound is 0.
json bound_ratio(const std::optional<int>& time, int bound) {
  if (!time || bound <= 0) return json(nullptr);
  return json(std::round(1000.0 * *time / bound) / 1000.0);
}
}  // namespace

json result_json(const planners::MissionSpec& spec, const sim::MissionResult& r) {
  const auto total = r.totals();
  json j;
  j["algorithm"] = spec.algorithm;
  j["uavs"] = spec.params.uavs;
  j["s1"] = spec.params.s1;
  j["s2"] = spec.params.s2;
  j["seed"] = spec.seed;
  j["complete"] = r.complete;
  j["T_c"] = seconds_json(spec.params, r.t_c);
  j["T_m"] = seconds_json(spec.params, r.t_m);
  if (spec.params.speed_m_s || spec.params.climb_speed_m_s) {  // only then: other results keep keys
    j["step_seconds"] = spec.params.step_seconds();
    j["plane_change_steps"] = spec.params.plane_change_steps();
  }
  j["steps"] = r.steps;
  j["moves"] = total.moves;
  j["plane_changes"] = total.plane_changes;
  j["hovers"] = total.hovers;
  j["redundant_observations"] = r.redundant_observations;
  j["observations"] = r.observations;
  j["corroded_cells"] = r.corroded_cells;
  j["hull_cells"] = r.hull_cells;
  j["unreachable_cells"] = r.unreachable_cells;
  j["unreachable_z2_cells"] = r.unreachable_z2_cells;
  j["planner_seconds"] = r.planner_seconds;
  j["tsp_solves"] = r.planner.tsp_solves;
  j["tsp_seconds"] = r.planner.tsp_seconds;
  j["tsp_max_seconds"] = r.planner.tsp_max_seconds;
  j["tsp_unproven"] = r.planner.tsp_unproven;
  j["tsp_fallbacks"] = r.planner.tsp_fallbacks;
  j["partition_fallbacks"] = r.planner.partition_fallbacks;
  j["replans"] = r.planner.replans;
  j["assignments"] = r.planner.assignments;
  j["failed_uavs"] = r.failed_uavs;
  j["separation"] = spec.params.separation;
  j["separation_conflicts"] = r.separation_conflicts;
  j["min_separation"] = r.min_separation ? json(*r.min_separation) : json(nullptr);
  json failed_at = json::array();
  for (const auto& u : r.uavs)
    failed_at.push_back(u.failed_at >= 0 ? json(u.failed_at) : json(nullptr));
  j["failed_at"] = std::move(failed_at);
  if (!spec.params.launch_sites.empty()) {  // only then, so that other results keep their keys
    json launch = json::array();
    for (const auto& u : r.uavs) {
      // Per UAV its sorties (take-off and landing times, site), flight and batteries swapped.
      json sorties = json::array();
      for (const auto& s : u.sorties) {
        sorties.push_back({{"takeoff", s.takeoff},
                           {"landing", s.landing >= 0 ? json(s.landing) : json(nullptr)},
                           {"site", s.site}});
      }
      launch.push_back({{"site", u.launch_site},
                        {"steps_away", u.steps_away},
                        {"landed_at", u.landed_at >= 0 ? json(u.landed_at) : json(nullptr)},
                        {"sorties", std::move(sorties)},
                        {"flight_s", world::battery_seconds(spec.params, u.flight_steps)},
                        {"swaps", u.swaps},
                        {"battery_crash", u.battery_crash}});
    }
    j["launch"] = std::move(launch);
    j["sorties"] = r.sorties();
    j["flight_s"] = world::battery_seconds(spec.params, total.flight_steps);
    j["battery_crashes"] = r.battery_crashes;
    j["min_battery_s"] = r.min_battery()
                             ? json(world::battery_seconds(spec.params, *r.min_battery()))
                             : json(nullptr);
    // The lower bound (docs/model.md §11, with what launch sites and endurance force) beside
    // T_c and T_m, and their ratios to it.
    j["bound_T_c"] = seconds_json(spec.params, r.bound_t_c);
    j["bound_T_m"] = seconds_json(spec.params, r.bound_t_m);
    j["T_c_ratio"] = bound_ratio(r.t_c, r.bound_t_c);
    j["T_m_ratio"] = bound_ratio(r.t_m, r.bound_t_m);
  }
  return j;
}

json spec_json(const planners::MissionSpec& spec, const std::string& hull_source) {
  json j;
  j["algorithm"] = spec.algorithm;
  j["planner_options"] = spec.planner_options;
  j["uavs"] = spec.params.uavs;
  j["s1"] = spec.params.s1;
  j["s2"] = spec.params.s2;
  j["theta"] = spec.params.theta_deg;
  j["start_z"] = spec.params.start_z;
  j["time_limit"] = spec.params.time_limit;
  if (spec.params.separation > 0) {
    j["separation"] = spec.params.separation;
    if (spec.params.strict_separation) j["strict_separation"] = true;
    if (!spec.params.deconflict) j["deconfliction"] = false;
  }
  j["seed"] = spec.seed;
  j["hull"] = hull_source;
  json zones = json::array();
  for (const auto& z : spec.corrosion.zones) {
    zones.push_back({{"x_begin", z.x_begin}, {"x_end", z.x_end}, {"p_c", z.p_c}, {"l_c", z.l_c}});
  }
  j["zones"] = std::move(zones);
  j["p_tp"] = spec.corrosion.p_tp;
  j["p_fp"] = spec.corrosion.p_fp;
  if (!spec.failures.empty()) j["failures"] = spec.failures.text();
  if (!spec.params.launch_sites.empty()) {
    json sites = json::array();
    for (const auto& c : spec.params.launch_sites) sites.push_back({c.x, c.y});
    j["launch"] = {{"sites", std::move(sites)}, {"transfer", spec.params.launch_transfer_s}};
    if (spec.params.takeoff_time_s) j["launch"]["takeoff_time"] = *spec.params.takeoff_time_s;
  }
  if (spec.params.endurance_s) {
    const auto b = world::battery_steps(spec.params);
    j["battery"] = {{"endurance", *spec.params.endurance_s},
                    {"reserve", world::battery_seconds(spec.params, b.reserve)},
                    {"swap_time", spec.params.swap_time_s}};
  }
  if (spec.params.speed_m_s) j["speed"] = *spec.params.speed_m_s;
  if (spec.params.climb_speed_m_s) j["climb_speed"] = *spec.params.climb_speed_m_s;
  // The user's maps, when they replaced the generated ones (the trace's prior/truth are theirs).
  if (spec.maps.prior) j["prior_file"] = spec.maps.prior->source;
  if (spec.maps.truth) j["truth_file"] = spec.maps.truth->source;
  return j;
}

}  // namespace hullinspect::io
