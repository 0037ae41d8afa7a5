#include <fmt/format.h>

#include "hullinspect/core/errors.hpp"
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

const std::vector<PlannerInfo>& registry() {
  static const std::vector<PlannerInfo> entries = {
      {"lawnmower",
       "baseline: partition, descend to z = 1, sweep strips of s1 rows bottom to top",
       {{"partitioner", std::string(partition::kDefaultPartitioner), "partitioner by name"},
        {"partition-seed", "0", "seed of the partitioner"}},
       &make_lawnmower},
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
