#include <fmt/format.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/coop_frontier_planner.hpp"
#include "hullinspect/planners/lawnmower_planner.hpp"
#include "hullinspect/planners/part_tsp_planner.hpp"
#include "hullinspect/planners/sweep_inspect_planner.hpp"
#include "hullinspect/planners/planner.hpp"

namespace hullinspect::planners {

namespace {

std::unique_ptr<Planner> make_lawnmower(const OptionMap& options) {
  OptionReader reader(options, "lawnmower");
  LawnmowerOptions o;
  o.partitioner = reader.get_string("partitioner", o.partitioner);
  o.partition_seed = static_cast<std::uint64_t>(reader.get_int("partition-seed", 0, 0, 1 << 30));
  reader.reject_unknown();
  partition::make_partitioner(o.partitioner);  // fail early on an unknown name
  return std::make_unique<LawnmowerPlanner>(o);
}

std::unique_ptr<Planner> make_coop_frontier(const OptionMap& options) {
  OptionReader reader(options, "coop-frontier");
  CoopFrontierOptions o;
  o.alpha = reader.get_double("alpha", o.alpha, 0.0, 1.0);
  o.beta = reader.get_double("beta", o.beta, 0.0, 1e6);
  o.base_utility = reader.get_double("base-utility", o.base_utility, 0.0, 1e6);
  o.radius_factor = reader.get_double("radius-factor", o.radius_factor, 0.0, 1e3);
  o.endgame_stay_low = reader.get_bool("endgame-stay-low", o.endgame_stay_low);
  reader.reject_unknown();
  return std::make_unique<CoopFrontierPlanner>(o);
}

std::unique_ptr<Planner> make_sweep_inspect(const OptionMap& options) {
  OptionReader reader(options, "sweep-inspect");
  SweepInspectOptions o;
  o.partitioner = reader.get_string("partitioner", o.partitioner);
  o.partition_seed = static_cast<std::uint64_t>(reader.get_int("partition-seed", 0, 0, 1 << 30));
  o.help = reader.get_bool("help", o.help);
  o.inspect_on_the_way = reader.get_bool("inspect-on-the-way", o.inspect_on_the_way);
  o.radius_factor = reader.get_double("radius-factor", o.radius_factor, 0.0, 1e3);
  o.prior_weights = reader.get_bool("prior-weights", o.prior_weights);
  o.prior_first = reader.get_bool("prior-first", o.prior_first);
  reader.reject_unknown();
  partition::make_partitioner(o.partitioner);  // fail early on an unknown name
  return std::make_unique<SweepInspectPlanner>(o);
}

std::unique_ptr<Planner> make_part_tsp(const OptionMap& options, bool use_prior, bool oracle = false) {
  OptionReader reader(options, oracle ? "oracle-part-tsp" : use_prior ? "part-tsp" : "part-tsp0");
  PartTspOptions o;
  o.use_prior = use_prior;
  o.oracle = oracle;
  o.r1 = reader.get_int("r1", o.r1, 0, 1 << 20);
  o.r2 = reader.get_int("r2", o.r2, 0, 1 << 20);
  o.tsp_solver = reader.get_string("tsp-solver", o.tsp_solver);
  o.partitioner = reader.get_string("partitioner", o.partitioner);
  o.partition_seed = static_cast<std::uint64_t>(reader.get_int("partition-seed", 0, 0, 1 << 30));
  o.skip_resolved = reader.get_bool("skip-resolved", o.skip_resolved);
  o.trim_ends = reader.get_bool("trim-ends", o.trim_ends);
  // "tsp.<key>=<value>" goes to the TSP solver as its option <key> (it checks them itself).
  for (const auto& [key, value] : options) {
    if (key.rfind("tsp.", 0) == 0) {
      o.tsp_solver_options[key.substr(4)] = reader.get_string(key, value);
    }
  }
  reader.reject_unknown();
  partition::make_partitioner(o.partitioner);  // fail early on an unknown name
  return std::make_unique<PartTspPlanner>(o);  // builds the TSP solver: fails on an unknown name
}

std::unique_ptr<Planner> make_part_tsp_with_prior(const OptionMap& options) {
  return make_part_tsp(options, true);
}
std::unique_ptr<Planner> make_part_tsp_without_prior(const OptionMap& options) {
  return make_part_tsp(options, false);
}
std::unique_ptr<Planner> make_oracle_part_tsp(const OptionMap& options) {
  return make_part_tsp(options, true, true);
}

std::vector<OptionSpec> part_tsp_options() {
  const PartTspOptions d;
  return {
      {"r1", std::to_string(d.r1), "steps since the last detection before descending"},
      {"r2", std::to_string(d.r2),
       "steps since the last inspection (or arrival at z = 1) before ascending"},
      {"tsp-solver", d.tsp_solver, "segment-TSP solver by name (exact, dfj-iterative, heuristic)"},
      {"partitioner", std::string(partition::kDefaultPartitioner), "partitioner by name"},
      {"partition-seed", "0", "seed of the partitioner"},
      {"skip-resolved", "false",
       "refinement: drop plan segments whose targets are all resolved (re-plan when none is left)"},
      {"trim-ends", "false", "refinement: pull segment ends in by the footprint half-width"},
      {"tsp.<key>", "", "option <key> of the TSP solver (e.g. tsp.dp_max_segments=12 for exact)"}};
}

const std::vector<PlannerInfo>& registry() {
  static const std::vector<PlannerInfo> entries = {
      {"lawnmower",
       "baseline: partition, descend to z = 1, sweep strips of s1 rows bottom to top",
       {{"partitioner", std::string(partition::kDefaultPartitioner), "partitioner by name"},
        {"partition-seed", "0", "seed of the partitioner"}},
       &make_lawnmower},
      {"part-tsp",
       "partition; per-UAV local maps from own sensing; FSM plane changes; segment TSP (uses the "
       "prior)",
       part_tsp_options(), &make_part_tsp_with_prior},
      {"part-tsp0", "Part-TSP ignoring the prior (local maps start without its 2s)",
       part_tsp_options(), &make_part_tsp_without_prior},
      {"coop-frontier",
       "cooperative frontier exploration on the shared map with prior/detection utilities and "
       "close-up inspection of detections (model.md §5.4)",
       {{"alpha", fmt::format("{}", CoopFrontierOptions{}.alpha),
         "weight of the prior term 1/d_HP in the frontier utility (eq. 13), [0, 1]"},
        {"beta", fmt::format("{}", CoopFrontierOptions{}.beta),
         "weight of the travel term 1/d(r, f) in the assignment (eq. 15), >= 0"},
        {"base-utility", fmt::format("{}", CoopFrontierOptions{}.base_utility),
         "constant added to every frontier utility so eq. 16 keeps spreading the fleet when eq. 13 "
         "is 0 (paper: 0)"},
        {"radius-factor", fmt::format("{}", CoopFrontierOptions{}.radius_factor),
         "close-up inspection radius in units of the standoff difference dz (paper: 2)"},
        {"endgame-stay-low", CoopFrontierOptions{}.endgame_stay_low ? "true" : "false",
         "when no frontier is left, stay at z = 1 and take the next unclaimed corrosion cell"}},
       &make_coop_frontier},
      {"sweep-inspect",
       "beyond the paper: sweep the region at z = 2 in strips of s2 rows, inspect detections as "
       "they come abreast, then help with the nearest unclaimed work anywhere (docs/beyond.md)",
       {{"partitioner", std::string(partition::kDefaultPartitioner), "partitioner by name"},
        {"partition-seed", "0", "seed of the partitioner"},
        {"help", "true", "after its sweep a UAV takes work anywhere (false: only its own region's)"},
        {"inspect-on-the-way", "true",
         "descend when a detection is abreast (false: inspect only after the sweep)"},
        {"radius-factor", "1", "inspect detections within radius-factor * s2 of the descent point"},
        {"prior-weights", "false", "DARP weighted by the expected work per cell (prior-aware)"},
        {"prior-first", "true", "first inspect the prior's cells of the region at z = 1, then sweep"}},
       &make_sweep_inspect},
      {"oracle-part-tsp",
       "BOUND, not a planner: Part-TSP whose local maps start from the ground truth C instead of "
       "the prior (sees the truth; docs/beyond.md)",
       part_tsp_options(), &make_oracle_part_tsp, true},
  };
  return entries;
}

}  // namespace

std::span<const PlannerInfo> planner_registry() { return registry(); }

std::unique_ptr<Planner> make_planner(std::string_view name, const OptionMap& options) {
  std::string names;
  for (const auto& info : registry()) {
    if (info.name == name) return info.make(options);
    names += (names.empty() ? "" : ", ") + info.name;
  }
  throw ParameterError("algorithm", fmt::format("unknown algorithm '{}' (known: {})", name, names));
}

}  // namespace hullinspect::planners
