#pragma once
// Readers of the exported waypoint files (docs/export.md), so tests (and users' tools) can check an
// export against its trace. Each throws InputError(source, line, problem) on a malformed file.

#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/io/geo_reference.hpp"

namespace hullinspect::io {

/// One waypoint as a file gives it; fields a format lacks stay at their defaults.
struct ReadWaypoint {
  double t = -1;               ///< seconds (csv, path); −1 when the format has no time (qgc, wpl)
  double x = 0, y = 0, z = 0;  ///< ship frame (csv, path)
  double yaw_deg = 0;          ///< csv: ship-frame yaw; qgc/wpl: compass heading
  int plane = 0;               ///< csv only
  std::string action;          ///< csv only
  double hold_s = 0;           ///< qgc, wpl: MAV_CMD_NAV_WAYPOINT param 1
  GeoPoint geo;                ///< qgc, wpl: lat, lon and the altitude relative to home
};

struct ReadPlan {
  std::vector<ReadWaypoint> waypoints;
  GeoPoint home;            ///< qgc, wpl
  double cruise_speed = 0;  ///< qgc
};

ReadPlan read_export_csv(std::string_view text, const std::string& source);
ReadPlan read_qgc_plan(std::string_view text, const std::string& source);
ReadPlan read_wpl(std::string_view text, const std::string& source);
ReadPlan read_path_yaml(std::string_view text, const std::string& source);

}  // namespace hullinspect::io
