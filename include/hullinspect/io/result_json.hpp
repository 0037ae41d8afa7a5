#pragma once

#include <nlohmann/json.hpp>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/sim/mission_result.hpp"

namespace hullinspect::io {

/// The one-object summary printed by `hullinspect run --json` (docs/formats.md#run-json).
nlohmann::json result_json(const planners::MissionSpec& spec, const sim::MissionResult& result);

/// The mission's parameters as recorded in traces and manifests.
nlohmann::json spec_json(const planners::MissionSpec& spec, const std::string& hull_source);

}  // namespace hullinspect::io
