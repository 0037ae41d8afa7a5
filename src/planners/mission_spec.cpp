#include "hullinspect/planners/mission_spec.hpp"

namespace hullinspect::planners {

void validate(const MissionSpec& spec, const world::HullMask& hull) {
  world::validate(spec.params, hull);
  world::validate(spec.corrosion, hull);
  world::validate(spec.failures, spec.params.uavs);
  make_planner(spec.algorithm, spec.planner_options);
}

sim::MissionResult run_mission(const MissionSpec& spec, const world::HullMask& hull,
                               const MissionOptions& options) {
  validate(spec, hull);
  auto instance = world::generate_instance(hull, spec.corrosion, spec.seed);
  world::apply(spec.maps, instance);
  auto planner = make_planner(spec.algorithm, spec.planner_options);
  MissionOptions with_failures = options;
  if (with_failures.failures.empty()) with_failures.failures = spec.failures;
  return run_mission(hull, instance, spec.params, *planner, with_failures);
}

}  // namespace hullinspect::planners
