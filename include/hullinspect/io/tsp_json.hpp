#pragma once
// The segment-TSP instance and solution formats of `hullinspect tsp` (docs/tsp.md):
//   instance  {"start": [x, y], "segments": [[[x1, y1], [x2, y2]], ...]}
//   solution  {"length": L, "optimal": bool, "order": [{"segment": i, "reversed": bool}, ...],
//              "seconds": s}

#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "hullinspect/tsp/segment_tsp.hpp"

namespace hullinspect::io {

/// Coordinates of an instance must lie within ±kTspCoordinateLimit.
inline constexpr int kTspCoordinateLimit = 1'000'000;

/// Parses an instance; every error is an InputError naming `source` and the offending field, e.g.
/// "segments[3][1]: expected [x, y] integers".
tsp::SegmentTsp parse_tsp_instance(std::string_view text, const std::string& source);
/// Reads and parses an instance file.
tsp::SegmentTsp read_tsp_instance(const std::filesystem::path& path);

nlohmann::ordered_json tsp_instance_json(const tsp::SegmentTsp& problem);
nlohmann::ordered_json tsp_solution_json(const tsp::TspSolution& solution);

}  // namespace hullinspect::io
