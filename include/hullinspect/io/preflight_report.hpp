#pragma once
// The pre-flight report of an export (docs/export.md "Pre-flight report"): per UAV and sortie the
// launch site, waypoints, distance and flight time and the files each format needs; the hull
// cells no allowed position can reach and those no footprint of the exported flights contains;
// and every warning (what a format could not carry, sorties split by a waypoint cap, an
// incomplete plan). Written as JSON, Markdown and an SVG picture of the flights on the grid.

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "hullinspect/io/export.hpp"

namespace hullinspect::io {

/// The report's data. `trace` is the planned mission's (for unreachable cells and completeness).
nlohmann::json preflight_report(const nlohmann::json& trace, const ExportPlan& plan,
                                const std::vector<ExportFormat>& formats,
                                const ExportSettings& settings,
                                const std::optional<GeoReference>& geo);

/// The report as Markdown (tables per sortie, the cells, the warnings, the picture).
std::string preflight_markdown(const nlohmann::json& report);

/// The picture: the grid (hull cells grey, no-fly positions red, unseen cells black), each
/// sortie's flight as a coloured line and the launch sites as circles.
std::string preflight_svg(const nlohmann::json& trace, const ExportPlan& plan,
                          const ExportSettings& settings);

}  // namespace hullinspect::io
