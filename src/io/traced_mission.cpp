#include "hullinspect/io/traced_mission.hpp"

#include "hullinspect/io/result_json.hpp"
#include "hullinspect/io/trace_recorder.hpp"
#include "hullinspect/planners/mission.hpp"

namespace hullinspect::io {

TracedMission run_traced_mission(const planners::MissionSpec& spec, const world::HullMask& hull) {
  const auto starts = planners::validate(spec, hull);
  const auto instance = planners::mission_instance(spec, hull);
  TraceRecorder recorder(instance, spec_json(spec, hull.source()));
  planners::MissionOptions options;
  options.observers.push_back(&recorder);
  TracedMission out;
  out.result = planners::run_mission(spec, hull, instance, starts, options);
  out.trace = recorder.finish(out.result);
  return out;
}

}  // namespace hullinspect::io
