// The built-in planners and their declared options (docs/architecture.md, "Parameters and
// registries"). Each option is declared once here; defaults are the options structs' initialisers.

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/registry_name.hpp"
#include "hullinspect/planners/coop_frontier_planner.hpp"
#include "hullinspect/planners/lawnmower_planner.hpp"
#include "hullinspect/planners/part_tsp_planner.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/planners/prior_weights.hpp"
#include "hullinspect/planners/sweep_inspect_planner.hpp"

namespace hullinspect::planners {

namespace {

std::vector<std::string> partitioner_names() {
  return partition::partitioners().names();
}
std::vector<std::string> tsp_solver_names() {
  return tsp::tsp_solvers().names();
}

constexpr long long kMaxPartitionSeed = 1 << 30;

Params<LawnmowerOptions> lawnmower_params() {
  Params<LawnmowerOptions> p("lawnmower");
  p.choice("partitioner", &LawnmowerOptions::partitioner, partitioner_names, "partitioner by name")
      .integer("partition-seed", &LawnmowerOptions::partition_seed, 0, kMaxPartitionSeed,
               "seed of the partitioner")
      .nested(
          "partitioner", &LawnmowerOptions::partitioner_options,
          [](const LawnmowerOptions& o, const OptionMap& m) {
            return partition::resolve_partitioner_options(o.partitioner, m);
          },
          "option <key> of the partitioner (e.g. partitioner.iteration-limit=4000 for darp)");
  declare_prior_weight_options(p);
  return p;
}

Params<PartTspOptions> part_tsp_params(bool use_prior, bool oracle = false) {
  PartTspOptions defaults;
  defaults.use_prior = use_prior;
  defaults.oracle = oracle;
  Params<PartTspOptions> p(oracle      ? "oracle-part-tsp"
                           : use_prior ? "part-tsp"
                                       : "part-tsp0",
                           defaults);
  p.integer("r1", &PartTspOptions::r1, 0, 1 << 20,
            "steps since the last detection before descending")
      .integer("r2", &PartTspOptions::r2, 0, 1 << 20,
               "steps since the last inspection (or arrival at z = 1) before ascending")
      .choice("tsp-solver", &PartTspOptions::tsp_solver, tsp_solver_names,
              "segment-TSP solver by name")
      .integer("tsp-max-segments", &PartTspOptions::tsp_max_segments, 0, 1 << 20,
               "a plan over more segments is ordered by local search, without a proof (0 = no "
               "cap)")
      .choice("partitioner", &PartTspOptions::partitioner, partitioner_names, "partitioner by name")
      .integer("partition-seed", &PartTspOptions::partition_seed, 0, kMaxPartitionSeed,
               "seed of the partitioner")
      .flag("skip-resolved", &PartTspOptions::skip_resolved,
            "refinement: drop plan segments whose targets are all resolved (re-plan when none is "
            "left)")
      .flag("trim-ends", &PartTspOptions::trim_ends,
            "refinement: pull segment ends in by the footprint half-width")
      .nested(
          "tsp", &PartTspOptions::tsp_solver_options,
          [](const PartTspOptions& o, const OptionMap& m) {
            return tsp::resolve_tsp_solver_options(o.tsp_solver, m);
          },
          "option <key> of the TSP solver (e.g. tsp.dp-max-segments=12 for exact)")
      .nested(
          "partitioner", &PartTspOptions::partitioner_options,
          [](const PartTspOptions& o, const OptionMap& m) {
            return partition::resolve_partitioner_options(o.partitioner, m);
          },
          "option <key> of the partitioner (e.g. partitioner.iteration-limit=4000 for darp)");
  declare_prior_weight_options(p);
  p.flag("share-work", &PartTspOptions::share_work,
         "beyond the paper: a UAV that is done takes over a failed UAV's region, else part of the "
         "most loaded UAV's remaining work (docs/part-tsp.md)");
  return p;
}

Params<SweepInspectOptions> sweep_inspect_params() {
  Params<SweepInspectOptions> p("sweep-inspect");
  p.choice("partitioner", &SweepInspectOptions::partitioner, partitioner_names,
           "partitioner by name, for the regions where neither band pieces nor column slabs are "
           "4-connected")
      .integer("partition-seed", &SweepInspectOptions::partition_seed, 0, kMaxPartitionSeed,
               "seed of the partitioner")
      .flag("prior-first", &SweepInspectOptions::prior_first,
            "first tour the prior's cells of the region at z = 1, then sweep (false: sweep "
            "only)")
      .number("prior-trust", &SweepInspectOptions::prior_trust, 0.0, 1.0,
              "drop the prior when fewer than this fraction of its cells are corroded: at the "
              "start when the scenario's statistics say so, else once its first 10 cells are "
              "seen (0: never)")
      .number("low-sweep-above", &SweepInspectOptions::low_sweep_above, 0.0, 1.0,
              "sweep a corrosion zone's cells at z = 1, in bands of s1, when the fraction of them "
              "expected corroded (beyond the prior's toured cells) exceeds this (1: never)")
      .choice(
          "strips", &SweepInspectOptions::strips,
          [] {
            return std::vector<std::string>{"rows", "columns", "auto"};
          },
          "the sweep's bands of s2 cells: rows (flown along the hull), columns (flown up "
          "and down its height) or auto (per region, whichever is the shorter flight)")
      .flag("planned-returns", &SweepInspectOptions::planned_returns,
            "with batteries, end a sortie where that is cheapest along the sweep (false: where "
            "the sortie layer sends the UAV home)")
      .nested(
          "partitioner", &SweepInspectOptions::partitioner_options,
          [](const SweepInspectOptions& o, const OptionMap& m) {
            return partition::resolve_partitioner_options(o.partitioner, m);
          },
          "option <key> of the partitioner (e.g. partitioner.iteration-limit=4000 for darp)");
  declare_prior_weight_options(p);
  return p;
}

Params<CoopFrontierOptions> coop_frontier_params() {
  Params<CoopFrontierOptions> p("coop-frontier");
  p.number("alpha", &CoopFrontierOptions::alpha, 0.0, 1.0,
           "weight of the prior term 1/d_HP in the frontier utility (eq. 13)")
      .number("beta", &CoopFrontierOptions::beta, 0.0, 1e6,
              "weight of the travel term 1/d(r, f) in the assignment (eq. 15)")
      .number("base-utility", &CoopFrontierOptions::base_utility, 0.0, 1e6,
              "constant added to every frontier utility so eq. 16 keeps spreading the fleet when "
              "eq. 13 is 0 (paper: 0)")
      .number("radius-factor", &CoopFrontierOptions::radius_factor, 0.0, 1e3,
              "close-up inspection radius in units of the standoff difference dz (paper: 2)")
      .flag("endgame-stay-low", &CoopFrontierOptions::endgame_stay_low,
            "when no frontier is left, stay at z = 1 and take the next unclaimed corrosion cell");
  return p;
}

void add_builtins(PlannerRegistry& r) {
  r.add_builtin(make_entry<Planner, LawnmowerOptions>(
      "lawnmower", "baseline: partition, descend to z = 1, sweep strips of s1 rows bottom to top",
      lawnmower_params(),
      [](const LawnmowerOptions& o) { return std::make_unique<LawnmowerPlanner>(o); }));
  r.add_builtin(make_entry<Planner, PartTspOptions>(
      "part-tsp",
      "partition; per-UAV local maps from own sensing; FSM plane changes; segment TSP (uses the "
      "prior)",
      part_tsp_params(true),
      [](const PartTspOptions& o) { return std::make_unique<PartTspPlanner>(o); }));
  r.add_builtin(make_entry<Planner, PartTspOptions>(
      "part-tsp0", "Part-TSP ignoring the prior (local maps start without its 2s)",
      part_tsp_params(false),
      [](const PartTspOptions& o) { return std::make_unique<PartTspPlanner>(o); }));
  r.add_builtin(make_entry<Planner, CoopFrontierOptions>(
      "coop-frontier",
      "cooperative frontier exploration on the shared map with prior/detection utilities and "
      "close-up inspection of detections (docs/coop-frontier.md)",
      coop_frontier_params(),
      [](const CoopFrontierOptions& o) { return std::make_unique<CoopFrontierPlanner>(o); }));
  r.add_builtin(make_entry<Planner, SweepInspectOptions>(
      "sweep-inspect",
      "beyond the paper: sweep the region at z = 2 in bands of s2 rows or columns, inspect "
      "detections as they come abreast, then help with the nearest unclaimed work anywhere "
      "(docs/sweep-inspect.md)",
      sweep_inspect_params(),
      [](const SweepInspectOptions& o) { return std::make_unique<SweepInspectPlanner>(o); }));
  r.add_builtin(make_entry<Planner, PartTspOptions>(
      "oracle-part-tsp",
      "BOUND, not a planner: Part-TSP whose local maps start from the ground truth C instead of "
      "the prior (sees the truth; docs/model.md §11)",
      part_tsp_params(true, true),
      [](const PartTspOptions& o) { return std::make_unique<PartTspPlanner>(o); },
      /*sees_truth=*/true));
}

}  // namespace

PlannerRegistry& planners() {
  static PlannerRegistry registry("algorithm", "algorithm", &add_builtins);
  return registry;
}

std::vector<PlannerInfo> planner_registry() {
  return planners().entries();
}

std::unique_ptr<Planner> make_planner(std::string_view name, const OptionMap& options) {
  return planners().make(name, options);
}

OptionMap resolve_planner_options(std::string_view name, const OptionMap& options) {
  return planners().resolve(name, options);
}

PlannerRegistration::PlannerRegistration(PlannerInfo entry) {
  check_registry_name("planner", "algorithm", entry.name);
  planners().add(std::move(entry));
}

}  // namespace hullinspect::planners
