#pragma once
// Readers of the exported waypoint files (docs/export.md), so tests (and users' tools) can check an
// export against its trace. Each throws InputError(source, line, problem) on a malformed file.

#include <array>
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

/// One MAVLink mission item (qgc, wpl): its command and seven parameters (NaN where the file
/// leaves one unset).
struct ReadItem {
  int command = 0;
  int frame = 0;
  std::array<double, 7> params{};
};

struct ReadPlan {
  std::vector<ReadWaypoint> waypoints;  ///< qgc, wpl: the NAV_WAYPOINT items
  std::vector<ReadItem> items;          ///< qgc, wpl: every item, in order
  int firmware = 0;                     ///< qgc: mission.firmwareType
  GeoPoint home;                        ///< qgc, wpl
  double cruise_speed = 0;              ///< qgc
};

ReadPlan read_export_csv(std::string_view text, const std::string& source);
ReadPlan read_qgc_plan(std::string_view text, const std::string& source);
ReadPlan read_wpl(std::string_view text, const std::string& source);
ReadPlan read_path_yaml(std::string_view text, const std::string& source);

}  // namespace hullinspect::io
