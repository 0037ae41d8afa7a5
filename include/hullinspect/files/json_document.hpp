#pragma once
// Reads a JSON document (TSP instance, trace, manifest) so that every failure, including a number
// that no double holds (1e400), is one InputError "FILE:LINE: what: problem at FIELD".

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace hullinspect::io {

/// Parses `text`; `what` names the document kind in errors ("a JSON trace"). Throws InputError
/// naming `source`, the line and the field path (e.g. "segments[3][0]") of the first problem.
nlohmann::json parse_json_document(std::string_view text, const std::string& source,
                                   std::string_view what);

}  // namespace hullinspect::io
