#include "hullinspect/planners/mission_spec.hpp"

#include "hullinspect/core/errors.hpp"
#include "hullinspect/partition/partitioner.hpp"
#include "hullinspect/world/mission_params.hpp"

namespace hullinspect::planners {

std::vector<grid::Cell> validate(const MissionSpec& spec, const world::HullMask& hull) {
  auto starts = world::validate(spec.params, hull);
  world::validate(spec.corrosion, hull);
  world::validate(spec.failures, spec.params.uavs);
  make_planner(spec.algorithm, spec.planner_options);
  // A stripes partition is not 4-connected on some non-convex hulls. It depends only on the hull,
  // the starts and n, so find that out here (before an experiment's first mission), not mid-run.
  if (auto it = spec.planner_options.find("partitioner");
      it != spec.planner_options.end() && it->second == "stripes") {
    partition::PartitionRequest request;
    request.hull = &hull;
    request.starts = starts;
    try {
      (void)partition::make_partitioner("stripes")->partition(request);
    } catch (const ParameterError&) {
      throw;
    } catch (const LogicError&) {
      throw;
    } catch (const Error& e) {
      throw ParameterError("partitioner", e.what());
    }
  }
  return starts;
}

const world::CorrosionParams* prior_statistics(const MissionSpec& spec) {
  // The scenario describes the prior only when both maps were drawn from it.
  return spec.maps.empty() ? &spec.corrosion : nullptr;
}

MissionOptions with_spec(const MissionSpec& spec, MissionOptions options) {
  if (options.failures.empty()) options.failures = spec.failures;
  if (options.corrosion == nullptr) options.corrosion = prior_statistics(spec);
  return options;
}

world::Instance mission_instance(const MissionSpec& spec, const world::HullMask& hull) {
  auto instance = world::generate_instance(hull, spec.corrosion, spec.seed);
  world::apply(spec.maps, instance);
  return instance;
}

sim::MissionResult run_mission(const MissionSpec& spec, const world::HullMask& hull,
                               const world::Instance& instance, std::span<const grid::Cell> starts,
                               const MissionOptions& options) {
  // Failures the caller gives instead of the spec's were not part of validate(spec).
  if (!options.failures.empty()) world::validate(options.failures, spec.params.uavs);
  auto planner = make_planner(spec.algorithm, spec.planner_options);
  return run_validated_mission(hull, instance, spec.params, starts, *planner,
                               with_spec(spec, options));
}

sim::MissionResult run_mission(const MissionSpec& spec, const world::HullMask& hull,
                               const MissionOptions& options) {
  const auto starts = validate(spec, hull);
  return run_mission(spec, hull, mission_instance(spec, hull), starts, options);
}

}  // namespace hullinspect::planners
