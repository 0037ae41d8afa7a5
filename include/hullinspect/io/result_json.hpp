#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/sim/mission_result.hpp"

namespace hullinspect::io {

/// A time of the mission in seconds (steps × the step's duration; docs/model.md, "Speed and
/// time"): a JSON integer when it is whole (every time of the paper's model), null when empty.
nlohmann::json seconds_json(const world::MissionParams& params, const std::optional<int>& steps);
/// The same as text: "12 s", "6.25 s", or "—" when empty.
std::string seconds_text(const world::MissionParams& params, const std::optional<int>& steps);

/// The one-object summary printed by `hullinspect run --json` (docs/formats.md#run-json).
nlohmann::json result_json(const planners::MissionSpec& spec, const sim::MissionResult& result);

/// The mission's parameters as recorded in traces and manifests.
nlohmann::json spec_json(const planners::MissionSpec& spec, const std::string& hull_source);

}  // namespace hullinspect::io
