#pragma once
// The pre-flight report of an export (docs/export.md "Pre-flight report"): per UAV and sortie the
// launch site, waypoints, distance, flight time, battery margin and the files each format needs;
// the hull cells no allowed position can reach and those no footprint of the exported flights
// contains; and every warning (what a format could not carry, sorties split by a waypoint cap, an
// incomplete plan). Written as JSON, Markdown and an SVG picture of the flights on the grid.

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "hullinspect/io/export.hpp"

namespace hullinspect::io {

/// One take-off to landing of the planned mission (sim::SortieRecord in seconds).
struct PlannedSortie {
  double takeoff_s = 0;
  std::optional<double> landing_s;  ///< empty: still airborne when the plan ended
  int site = 0;                     ///< index of the launch site
};

/// The batteries the mission was planned with, for the battery margin of every sortie.
/// Without an endurance (`limited` false) flight is unlimited and no margin exists.
struct PreflightBattery {
  bool limited = false;
  double endurance_s = 0;
  double reserve_s = 0;
  double plan_end_s = 0;  ///< when the planned mission ended (for a sortie never landed)
  std::vector<std::vector<PlannedSortie>> sorties;  ///< per UAV, in flight order
};

/// The report's data. `trace` is the planned mission's (for unreachable cells and completeness).
/// With a limited battery each of the mission's sorties is a row: its flight time is the
/// mission's take-off to landing, its battery margin the endurance less that time, and a margin
/// below the reserve is a warning. Without one, a row per UAV and `battery_margin_s` null, with
/// the reason in `battery`.
nlohmann::json preflight_report(const nlohmann::json& trace, const ExportPlan& plan,
                                const std::vector<ExportFormat>& formats,
                                const ExportSettings& settings,
                                const std::optional<GeoReference>& geo,
                                const PreflightBattery& battery = {});

/// The report as Markdown (tables per sortie, the cells, the warnings, the picture).
std::string preflight_markdown(const nlohmann::json& report);

/// The picture: the grid (hull cells grey, no-fly positions red, unseen cells black), each
/// sortie's flight as a coloured line and the launch sites as circles.
std::string preflight_svg(const nlohmann::json& trace, const ExportPlan& plan,
                          const ExportSettings& settings);

}  // namespace hullinspect::io
