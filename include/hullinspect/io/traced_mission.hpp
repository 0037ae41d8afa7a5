#pragma once
// One mission run from its spec with a trace recorded (docs/trace-format.md): what `hullinspect
// run --trace` records, for callers that want the trace in memory (the Python module).

#include <nlohmann/json.hpp>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/sim/mission_result.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::io {

struct TracedMission {
  sim::MissionResult result;
  nlohmann::json trace;  ///< the whole trace, result included
};

/// Runs the mission `spec` describes on `hull` (the instance drawn from its seed, the user's maps
/// and failures applied, as planners::run_mission(spec, hull)) and records its trace.
TracedMission run_traced_mission(const planners::MissionSpec& spec, const world::HullMask& hull);

}  // namespace hullinspect::io
