#include "hullinspect/io/traced_mission.hpp"

#include "hullinspect/io/result_json.hpp"
#include "hullinspect/io/trace_recorder.hpp"
#include "hullinspect/planners/mission.hpp"

namespace hullinspect::io {

TracedMission run_traced_mission(const planners::MissionSpec& spec, const world::HullMask& hull) {
  planners::validate(spec, hull);
  auto instance = world::generate_instance(hull, spec.corrosion, spec.seed);
  world::apply(spec.maps, instance);
  auto planner = planners::make_planner(spec.algorithm, spec.planner_options);
  TraceRecorder recorder(instance, spec_json(spec, hull.source()));
  planners::MissionOptions options;
  options.observers.push_back(&recorder);
  options.failures = spec.failures;
  options.corrosion = planners::prior_statistics(spec);
  TracedMission out;
  out.result = planners::run_mission(hull, instance, spec.params, *planner, options);
  out.trace = recorder.finish(out.result);
  return out;
}

}  // namespace hullinspect::io
