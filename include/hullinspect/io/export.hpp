#pragma once
// Waypoint export of a mission trace (docs/export.md): every UAV's flown trajectory compressed to
// waypoints (io/waypoints.hpp), placed in the ship frame (io/ship_frame.hpp), optionally
// geo-referenced (io/geo_reference.hpp) and written as csv, a QGroundControl .plan, a
// `QGC WPL 110` file or a YAML nav_msgs/Path — one file per UAV.

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "hullinspect/io/geo_reference.hpp"
#include "hullinspect/io/ship_frame.hpp"
#include "hullinspect/io/waypoints.hpp"

namespace hullinspect::io {

enum class ExportFormat { kCsv, kQgc, kWpl, kPath };

/// "csv", "qgc", "wpl", "path"; throws ParameterError("format") for anything else.
ExportFormat parse_export_format(const std::string& name);
std::string_view to_string(ExportFormat format);

struct ExportWaypoint {
  GridWaypoint grid;
  ShipPose pose;
};

/// One UAV's waypoints.
struct UavWaypoints {
  int uav = 0;
  std::vector<ExportWaypoint> waypoints;
};

/// What every format writes: the frame, each UAV's waypoints and the mission's no-fly positions.
struct ExportPlan {
  ShipFrame frame;
  int plane_change_steps = 1;
  std::vector<UavWaypoints> uavs;
  std::vector<grid::Cell> no_fly;
};

/// Builds the plan of a validated trace; `source` (the trace or hull file the geometry came from)
/// is named when a waypoint's coordinates cannot be represented.
ExportPlan export_plan(const nlohmann::json& trace, const std::string& source = "trace");

struct ExportFile {
  std::string name;  ///< file name inside the output directory
  std::string content;
};

/// The names of the files export_files writes for `uavs` UAVs, known before any mission runs (so
/// a command can check its outputs first).
std::vector<std::string> export_file_names(ExportFormat format, int uavs, bool geo_referenced);

/// The files of one format: `uav<k>.csv`, `uav<k>.plan` (qgc), `uav<k>.waypoints` (wpl),
/// `uav<k>.path.yaml` (path; plus `hull_to_map.yaml` when geo-referenced). qgc and wpl need a
/// geo-reference: without one this throws ParameterError("origin").
std::vector<ExportFile> export_files(const ExportPlan& plan, ExportFormat format,
                                     const std::optional<GeoReference>& geo);

/// The hold time (s) a flight controller waits at waypoint `w` so that a vehicle flying at
/// `speed_mps` between waypoints arrives at the trace's times: the hold's duration, or the part of
/// a plane change its straight flight does not take.
double hold_seconds(const ExportWaypoint& w, const ExportWaypoint& previous, double speed_mps);

/// The cruise speed of an exported plan: one cell per second (model.md §1: a move takes one step).
double cruise_speed_mps(const ExportPlan& plan);

}  // namespace hullinspect::io
