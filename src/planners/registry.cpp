#include <fmt/format.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/coop_frontier_planner.hpp"
#include "hullinspect/planners/lawnmower_planner.hpp"
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

const std::vector<PlannerInfo>& registry() {
  static const std::vector<PlannerInfo> entries = {
      {"lawnmower",
       "baseline: partition, descend to z = 1, sweep strips of s1 rows bottom to top",
       {{"partitioner", std::string(partition::kDefaultPartitioner), "partitioner by name"},
        {"partition-seed", "0", "seed of the partitioner"}},
       &make_lawnmower},
      {"coop-frontier",
       "cooperative frontier exploration on the shared map with prior/detection utilities and "
       "close-up inspection of detections (SPEC 5.4)",
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
