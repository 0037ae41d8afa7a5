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
           "partitioner by name")
      .integer("partition-seed", &SweepInspectOptions::partition_seed, 0, kMaxPartitionSeed,
               "seed of the partitioner")
      .flag("help", &SweepInspectOptions::help,
            "after its sweep a UAV takes work anywhere (false: only its own region's)")
      .flag("inspect-on-the-way", &SweepInspectOptions::inspect_on_the_way,
            "descend when a detection is abreast (false: inspect only after the sweep)")
      .number("radius-factor", &SweepInspectOptions::radius_factor, 0.0, 1e3,
              "inspect detections within radius-factor * s2 of the descent point")
      .flag("prior-first", &SweepInspectOptions::prior_first,
            "first inspect the prior's cells of the region at z = 1, then sweep")
      .flag("resume-ahead", &SweepInspectOptions::resume_ahead,
            "after an inspection rejoin the strip up to s2/2 columns ahead (already seen) instead "
            "of where it was left")
      .flag("replan-rejoin", &SweepInspectOptions::replan_rejoin,
            "after an inspection plan the sweep anew from where the UAV is when that flight is "
            "shorter than the way back to the band and on")
      .flag("nearer-sweep-end", &SweepInspectOptions::nearer_sweep_end,
            "plan the sweep from where the prior's inspections ended, over the cells they did not "
            "see, from its nearer end (false: the whole region bottom-up from the start cell)")
      .number("prior-trust", &SweepInspectOptions::prior_trust, 0.0, 1.0,
              "stop the prior's inspections once fewer than this fraction of the prior cells "
              "seen so far were corroded (0: never)")
      .integer("prior-check-cells", &SweepInspectOptions::prior_check_cells, 1, 1000000,
               "prior cells to see before prior-trust applies")
      .flag("trust-statistics", &SweepInspectOptions::trust_statistics,
            "drop the prior at the start when the scenario's statistics make fewer than "
            "prior-trust of its cells corroded on average")
      .flag("take-over-prior", &SweepInspectOptions::take_over_prior,
            "a failed UAV's prior cells go at once to the nearest working UAV (false: they wait "
            "for the helpers)")
      .flag("take-over-sweep", &SweepInspectOptions::take_over_sweep,
            "a failed UAV's unswept cells go at once to the working UAVs, split so that they end "
            "together; each sweeps its share after its own strips (false: they wait for the "
            "helpers)")
      .flag("leave-to-low-sweep", &SweepInspectOptions::leave_to_low_sweep,
            "after a failure's re-split, a detection in another working UAV's share of the dense "
            "columns is left to that UAV's z = 1 sweep (false: whoever passes it descends)")
      .flag("pass-left-detections", &SweepInspectOptions::pass_left_detections,
            "after a failure's re-split, the sweep of the share a detection not yet inspected went "
            "to passes abreast of it and inspects it, also at z = 2 (false: a failed UAV's "
            "detections wait for the helpers)")
      .flag("two-block-sweep", &SweepInspectOptions::two_block_sweep,
            "after a failure's re-split, a share's dense part is swept at z = 1 as two blocks of "
            "columns, one after the other, where that is a shorter flight (false: one "
            "boustrophedon over its bands)")
      .flag("share-prior", &SweepInspectOptions::share_prior,
            "neighbours re-split their prior cells so that their tours end together (at the start "
            "and after a failure), and a UAV whose tour is done takes the part of the longest tour "
            "left that makes the two end earliest (false: each tours its region's prior cells)")
      .flag("yield-claims", &SweepInspectOptions::yield_claims,
            "a claimed target goes to a UAV nearer to it than its claimer (false: claims hold)")
      .choice(
          "strips", &SweepInspectOptions::strips,
          [] {
            return std::vector<std::string>{"rows", "columns", "auto"};
          },
          "the sweep's bands of s2 cells: rows (flown along the hull), columns (flown up "
          "and down its height) or auto (per region, whichever is the shorter flight)")
      .flag("trim-strip-ends", &SweepInspectOptions::trim_strip_ends,
            "fly a band only as far as the footprint needs to reach its ends")
      .flag("follow-clusters", &SweepInspectOptions::follow_clusters,
            "at z = 1 also look at the unobserved cells beside inspected ones (within the "
            "inspection radius) before climbing")
      .flag("inspect-viewpoints", &SweepInspectOptions::inspect_viewpoints,
            "at z = 1 fly to the position whose footprint takes in the most detections (and "
            "cells beside inspected ones) per step of flight, held until reached (false: the "
            "nearest cell's nearest viewpoint, chosen anew each step)")
      .flag("skip-seen-bands", &SweepInspectOptions::skip_seen_bands,
            "skip the rest of a band whose cells have all been observed already")
      .number("low-sweep-above", &SweepInspectOptions::low_sweep_above, 0.0, 1.0,
              "sweep a corrosion zone's cells at z = 1, in bands of s1, when the fraction of them "
              "expected corroded (beyond the prior's toured cells) exceeds this (1: never)")
      .integer("low-sweep-min-bands", &SweepInspectOptions::low_sweep_min_bands, 0, 1000000,
               "a UAV whose dense columns span at most this many bands of s1, among other cells, "
               "sweeps them at z = 2 with the rest (0: never)")
      .flag("share-sweep", &SweepInspectOptions::share_sweep,
            "a UAV whose sweep is done takes the last bands of the sweep that would end last, "
            "split so that the two end earliest, before it helps cell by cell")
      .flag("slab-partition", &SweepInspectOptions::slab_partition,
            "partition in column slabs (the stripes partitioner, same weights) where they are "
            "4-connected, else with the partitioner option")
      .flag("band-partition", &SweepInspectOptions::band_partition,
            "partition in pieces of one boustrophedon over the hull's column bands, of equal "
            "expected work, where they are 4-connected (else slab-partition's)")
      .flag("inspect-band-ends", &SweepInspectOptions::inspect_band_ends,
            "while sweeping also descend for a detected cell in the footprint that the flight's "
            "current leg comes no nearer to (beyond a band's trimmed end)")
      .flag("descend-when-level", &SweepInspectOptions::descend_when_level,
            "descend for a detection abreast only once it is no longer ahead on the leg, so that "
            "the z = 2 footprint has seen the rows beyond it (false: within s1/2 ahead)")
      .flag("plan-prior-tour", &SweepInspectOptions::plan_prior_tour,
            "visit the prior's cells in the order of a planned tour (nearest neighbour, 2-opt, "
            "Or-opt), planned again when its next cell was seen while it has at most 100 cells, "
            "else kept with the seen cells dropped (false: the nearest cell at every step)")
      .flag("approach-edge", &SweepInspectOptions::approach_edge,
            "fly to the sweep's first band along the region's edge row when that shortens the "
            "whole flight (the bands passed are flown only over the cells not yet seen)")
      .flag("own-band-first", &SweepInspectOptions::own_band_first,
            "also plan sweeps that begin at the UAV's own band (the bands on one side of it, "
            "whole or up to a cut near the UAV, then the rest), when that shortens the flight")
      .flag("balance-flights", &SweepInspectOptions::balance_flights,
            "without a prior tour, cut the band partition again so that the planned flights from "
            "the starts (plus expected inspections) end together")
      .integer("balance-rounds", &SweepInspectOptions::balance_rounds, 0, 100,
               "passes of balance-flights over the cuts (0: pieces of equal work)")
      .number("inspection-weight", &SweepInspectOptions::inspection_weight, 0.0, 100.0,
              "in the band partition, the inspections expected at a cell the sweep detects (its "
              "weight's excess over 1) count this many times (a toured prior cell's, "
              "prior-tour-weight times)")
      .number("prior-tour-weight", &SweepInspectOptions::prior_tour_weight, 0.0, 100.0,
              "with share-prior, in the band partition, a prior cell toured first counts its "
              "weight's excess over 1 this many times (share-prior re-splits the tours after the "
              "partition; without it, once)")
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
