#include "hullinspect/experiment/run_record.hpp"

#include <fmt/format.h>

#include "hullinspect/experiment/csv.hpp"
#include "hullinspect/experiment/run_row_check.hpp"
#include "hullinspect/world/battery.hpp"

namespace hullinspect::experiment {

namespace {

std::string optional_count(const std::optional<int>& n) {
  return n ? std::to_string(*n) : "";
}

/// A time of the mission in seconds (steps × the step; the step count itself without a speed).
std::string seconds_field(const world::MissionParams& timing, const std::optional<int>& steps) {
  return steps ? fmt::format("{}", timing.seconds(*steps)) : "";
}

template <class T>
std::string joined(const std::vector<world::CorrosionZone>& zones, T field) {
  std::string out;
  for (const auto& z : zones) out += fmt::format("{}{}", out.empty() ? "" : "/", field(z));
  return out;
}

}  // namespace

std::vector<std::string> runs_header() {
  return {"run_id",
          "cell_id",
          "scenario",
          "sweep",
          "sweep_value",
          "algorithm",
          "planner",
          "planner_options",
          "hull",
          "cell_size",
          "s1",
          "s2",
          "theta",
          "uavs",
          "start_z",
          "time_limit",
          "p_c",
          "l_c",
          "zone_bounds",
          "p_tp",
          "p_fp",
          "seed",
          "complete",
          "T_c",
          "T_m",
          "steps",
          "hull_cells",
          "corroded_cells",
          "detections",
          "observations",
          "redundant_observations",
          "moves",
          "hovers",
          "plane_changes",
          "steps_z1",
          "steps_z2",
          "steps_transit",
          "tsp_solves",
          "tsp_unproven",
          "tsp_fallbacks",
          "replans",
          "assignments",
          "failures",
          "failed_uavs",
          "bound_T_c",
          "bound_T_m",
          "unreachable_cells",
          "partition_fallbacks",
          "separation",
          "separation_conflicts",
          "min_separation",
          "sorties",
          "flight_s",
          "battery_crashes",
          "min_battery_s"};
}

std::vector<std::string> samples_header(const CurveGrid& grid) {
  std::vector<std::string> h = {"run_id"};
  const auto times = grid.times();
  for (int t : times) h.push_back(fmt::format("inspected_{}", t));
  for (int t : times) h.push_back(fmt::format("known_{}", t));
  return h;
}

std::vector<std::string> timings_header() {
  return {"run_id", "wall_seconds", "planner_seconds", "tsp_seconds", "tsp_max_seconds"};
}

int value_at(const std::vector<int>& series, int t) {
  if (series.empty()) return 0;
  const auto i = std::min(static_cast<std::size_t>(t), series.size() - 1);
  return series[i];
}

std::vector<std::string> run_parameter_fields(const ExperimentPlan& plan, const RunKey& run) {
  const auto& c = plan.config();
  const Cell& cell = plan.cells()[static_cast<std::size_t>(run.cell)];
  const auto& s = c.scenarios[static_cast<std::size_t>(cell.scenario)];
  const auto& a = c.algorithms[static_cast<std::size_t>(cell.algorithm)];
  const auto& zones = s.corrosion.zones;
  std::string options;
  for (const auto& [k, v] : a.options)
    options += fmt::format("{}{}={}", options.empty() ? "" : ";", k, v);
  std::string bounds = zones.empty() ? "" : std::to_string(zones.front().x_begin);
  for (const auto& z : zones) bounds += fmt::format("/{}", z.x_end);
  return {run.id,
          cell.id,
          s.name,
          s.sweep,
          s.sweep_value,
          a.label,
          a.planner,
          options,
          c.hull_spec,
          fmt::format("{}", c.cell_size),
          std::to_string(c.mission.s1),
          std::to_string(c.s2[static_cast<std::size_t>(cell.s2)]),
          fmt::format("{}", c.mission.theta),
          std::to_string(c.uavs[static_cast<std::size_t>(cell.uavs)]),
          std::to_string(c.mission.start_z),
          std::to_string(c.mission.time_limit),
          joined(zones, [](const world::CorrosionZone& z) { return fmt::format("{}", z.p_c); }),
          joined(zones, [](const world::CorrosionZone& z) { return std::to_string(z.l_c); }),
          bounds,
          fmt::format("{}", s.corrosion.p_tp),
          fmt::format("{}", s.corrosion.p_fp),
          std::to_string(run.seed)};
}

std::string run_failures_field(const ExperimentPlan& plan, const RunKey& run) {
  const auto& c = plan.config();
  const Cell& cell = plan.cells()[static_cast<std::size_t>(run.cell)];
  return c.scenarios[static_cast<std::size_t>(cell.scenario)].failures.text();
}

RunRecord make_record(const ExperimentPlan& plan, const RunKey& run, const sim::MissionResult& r,
                      double wall_seconds) {
  const auto& c = plan.config();
  const auto total = r.totals();

  const auto timing = c.timing();
  RunRecord record;
  auto fields = run_parameter_fields(plan, run);
  for (std::string value : {std::string(r.complete ? "1" : "0"),
                            seconds_field(timing, r.t_c),
                            seconds_field(timing, r.t_m),
                            std::to_string(r.steps),
                            std::to_string(r.hull_cells),
                            std::to_string(r.corroded_cells),
                            std::to_string(r.detections),
                            std::to_string(r.observations),
                            std::to_string(r.redundant_observations),
                            std::to_string(total.moves),
                            std::to_string(total.hovers),
                            std::to_string(total.plane_changes),
                            std::to_string(total.steps_z1),
                            std::to_string(total.steps_z2),
                            std::to_string(total.steps_transit),
                            std::to_string(r.planner.tsp_solves),
                            std::to_string(r.planner.tsp_unproven),
                            std::to_string(r.planner.tsp_fallbacks),
                            std::to_string(r.planner.replans),
                            std::to_string(r.planner.assignments),
                            run_failures_field(plan, run),
                            std::to_string(r.failed_uavs),
                            seconds_field(timing, r.bound_t_c),
                            seconds_field(timing, r.bound_t_m),
                            std::to_string(r.unreachable_cells),
                            std::to_string(r.planner.partition_fallbacks),
                            std::to_string(plan.config().mission.separation),
                            std::to_string(r.separation_conflicts),
                            optional_count(r.min_separation),
                            std::to_string(r.sorties()),
                            seconds_field(timing, total.flight_steps),
                            std::to_string(r.battery_crashes),
                            seconds_field(timing, r.min_battery())}) {
    fields.push_back(std::move(value));
  }
  record.runs = csv_line(fields);

  const auto times = c.curve.times();
  std::string samples = run.id;
  samples.reserve(times.size() * 10);
  for (int t : times) samples += fmt::format(",{}", value_at(r.inspected_series, t));
  for (int t : times) samples += fmt::format(",{}", value_at(r.known_series, t));
  record.samples = std::move(samples);

  record.timings = csv_line({run.id, fmt::format("{:.6f}", wall_seconds),
                             fmt::format("{:.6f}", r.planner_seconds),
                             fmt::format("{:.6f}", r.planner.tsp_seconds),
                             fmt::format("{:.6f}", r.planner.tsp_max_seconds)});
  return record;
}

}  // namespace hullinspect::experiment
