#pragma once
// What can be chosen by name — planners, partitioners, TSP solvers, scenarios, presets — with their
// declared options, as read by `hullinspect list` and the Python module.

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace hullinspect::experiment {

/// "planners", "partitioners", "tsp-solvers", "scenarios", "presets".
const std::vector<std::string>& catalog_kinds();

/// An array of {"kind", "name", "description", "sees_truth", "options": [{"name", "type",
/// "default", "range", "description"}]} for one kind (or every kind when `kind` is empty), in
/// registration order. Throws ParameterError("kind", …) for an unknown kind.
nlohmann::json catalog_json(std::string_view kind = {});

}  // namespace hullinspect::experiment
