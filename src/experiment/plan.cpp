#include "hullinspect/experiment/plan.hpp"

#include <fmt/format.h>

#include "config_mission.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/hash.hpp"
#include "hullinspect/planners/planner.hpp"

namespace hullinspect::experiment {

namespace {

// Only configs with launch sites say so in the run key, so that every other run keeps its id.
std::string launch_key(const ExperimentConfig& c) {
  if (c.launch_sites.empty()) return {};
  std::string key = "|launch=";
  for (const auto& s : c.launch_sites) key += fmt::format("{},{};", s.x, s.y);
  key += fmt::format("transfer={}", c.mission.launch_transfer);
  if (c.mission.takeoff_time) key += fmt::format(";takeoff={}", *c.mission.takeoff_time);
  if (c.mission.endurance) {
    key += fmt::format("|battery={};swap={}", *c.mission.endurance, c.mission.swap_time);
    if (c.mission.reserve) key += fmt::format(";reserve={}", *c.mission.reserve);
  }
  return key;
}

// Likewise only configs with a speed: every other run keeps its id.
std::string speed_key(const ExperimentConfig& c) {
  std::string key;
  if (c.mission.speed) key += fmt::format("|speed={}", *c.mission.speed);
  if (c.mission.climb_speed) key += fmt::format("|climb_speed={}", *c.mission.climb_speed);
  return key;
}

// Doubles are written in their shortest round-trip form, so the string (and the id) only changes
// when a value does.
std::string canonical_cell(const ExperimentConfig& c, const Cell& cell) {
  const auto& s = c.scenarios[static_cast<std::size_t>(cell.scenario)];
  const auto& a = c.algorithms[static_cast<std::size_t>(cell.algorithm)];
  std::string zones;
  for (const auto& z : s.corrosion.zones) {
    zones +=
        fmt::format("{}{}:{}:{}:{}", zones.empty() ? "" : ";", z.x_begin, z.x_end, z.p_c, z.l_c);
  }
  std::string options;
  for (const auto& [k, v] : a.options)
    options += fmt::format("{}{}={}", options.empty() ? "" : ";", k, v);
  return fmt::format(
             "hullinspect-run/"
             "1|hull={}|cell_size={}|scenario={}|zones={}|p_tp={}|p_fp={}|s1={}|s2={}|"
             "theta={}|uavs={}|start_z={}|time_limit={}|algorithm={}|planner={}|options={}",
             c.hull_hash, c.cell_size, s.name, zones, s.corrosion.p_tp, s.corrosion.p_fp,
             c.mission.s1, c.s2[static_cast<std::size_t>(cell.s2)], c.mission.theta,
             c.uavs[static_cast<std::size_t>(cell.uavs)], c.mission.start_z, c.mission.time_limit,
             a.label, a.planner, options) +
         // Only scenarios with failures or their own no-fly zones say so, so that every other run
         // keeps its id.
         (s.failures.empty() ? std::string() : "|failures=" + s.failures.text()) +
         (s.no_fly_spec.is_null() ? std::string()
                                  : "|no_fly=" + s.no_fly_spec.at("hash").get<std::string>()) +
         // The user's maps by content, as no-fly zones: only configs with them say so.
         (c.prior_hash.empty() ? std::string() : "|prior=" + c.prior_hash) +
         (c.truth_hash.empty() ? std::string() : "|truth=" + c.truth_hash) + launch_key(c) +
         speed_key(c) +
         (c.mission.separation == 0 ? std::string()
                                    : fmt::format("|separation={}", c.mission.separation));
}

}  // namespace

ExperimentPlan::ExperimentPlan(ExperimentConfig config) : config_(std::move(config)) {
  if (config_.hull) {
    // Every algorithm's effective options (defaults included) define its cells, the manifest and
    // runs.csv, so an option spelled out at its default names the same experiment as one left out.
    for (auto& a : config_.algorithms) {
      try {
        a.options = planners::resolve_planner_options(a.planner, a.options);
      } catch (const ParameterError& e) {
        throw InputError(config_.source, a.line, e.what());
      }
    }
  }
  const auto& c = config_;
  for (int sc = 0; sc < static_cast<int>(c.scenarios.size()); ++sc) {
    for (int s2 = 0; s2 < static_cast<int>(c.s2.size()); ++s2) {
      for (int n = 0; n < static_cast<int>(c.uavs.size()); ++n) {
        for (int a = 0; a < static_cast<int>(c.algorithms.size()); ++a) {
          Cell cell{sc, s2, n, a, "", ""};
          cell.canonical = canonical_cell(c, cell);
          cell.id = stable_id(cell.canonical);
          if (c.hull) validate_cell(cell);
          cells_.push_back(std::move(cell));
        }
      }
    }
  }
  for (int ci = 0; ci < static_cast<int>(cells_.size()); ++ci) {
    for (int si = 0; si < static_cast<int>(c.seeds.size()); ++si) {
      const std::uint64_t seed = c.seeds[static_cast<std::size_t>(si)];
      RunKey run{ci, si, seed,
                 stable_id(fmt::format("{}|seed={}", cells_[static_cast<std::size_t>(ci)].canonical,
                                       seed))};
      if (!position_.emplace(run.id, static_cast<int>(runs_.size())).second) {
        throw LogicError(fmt::format("run id {} is not unique (hash collision)", run.id));
      }
      runs_.push_back(std::move(run));
    }
  }
}

int ExperimentPlan::run_position(const std::string& id) const {
  auto it = position_.find(id);
  return it == position_.end() ? -1 : it->second;
}

planners::MissionSpec ExperimentPlan::mission(const RunKey& run) const {
  return mission(cells_[static_cast<std::size_t>(run.cell)], run.seed);
}

planners::MissionSpec ExperimentPlan::mission(const Cell& cell, std::uint64_t seed) const {
  const auto& c = config_;
  const auto& a = c.algorithms[static_cast<std::size_t>(cell.algorithm)];
  planners::MissionSpec spec;
  spec.algorithm = a.planner;
  spec.planner_options = a.options;
  planners::set_mission_params(c.mission, spec.params);
  spec.params.uavs = c.uavs[static_cast<std::size_t>(cell.uavs)];
  spec.params.s2 = c.s2[static_cast<std::size_t>(cell.s2)];
  spec.params.cell_size_m = c.cell_size;
  spec.params.launch_sites = c.launch_sites;
  const ScenarioSpec& scenario = c.scenarios[static_cast<std::size_t>(cell.scenario)];
  spec.params.no_fly = scenario.no_fly ? scenario.no_fly : c.no_fly;
  spec.corrosion = scenario.corrosion;
  spec.failures = scenario.failures;
  spec.seed = seed;
  spec.maps = c.maps;
  return spec;
}

void ExperimentPlan::validate_cell(const Cell& cell) const {
  try {
    planners::validate(mission(cell, 0), *config_.hull);
  } catch (const ParameterError& e) {
    // Point at the value that made this cell invalid.
    const std::string& name = e.name();
    int line = 0;
    if (name == "uavs") {
      line = config_.line_of(fmt::format("uavs[{}]", cell.uavs));
    } else if (name == "s2") {
      line = config_.line_of(fmt::format("s2[{}]", cell.s2));
      if (line == 0) line = config_.line_of("s1");
    } else if (name == "p_c" || name == "l_c" || name == "p_tp" || name == "p_fp" ||
               name == "zones") {
      line = config_.scenarios[static_cast<std::size_t>(cell.scenario)].line;
    } else if (name == "algorithm" || name == "partitioner" ||
               name.find('.') != std::string::npos) {
      line = config_.algorithms[static_cast<std::size_t>(cell.algorithm)].line;
    } else {
      // A mission option names its config key ("battery.endurance") and that key's line.
      const auto [key, key_line] = detail::config_key_of(config_, name);
      throw InputError(config_.source, key_line, fmt::format("{}: {}", key, e.problem()));
    }
    throw InputError(config_.source, line, e.what());
  }
}

}  // namespace hullinspect::experiment
