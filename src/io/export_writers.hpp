#pragma once
// The per-format writers behind io::export_files (one UAV, one file each).

#include <optional>
#include <string>

#include "hullinspect/io/export.hpp"

namespace hullinspect::io::detail {

std::string write_csv(const ExportPlan& plan, const UavWaypoints& uav,
                      const std::optional<GeoReference>& geo);
std::string write_qgc_plan(const ExportPlan& plan, const UavWaypoints& uav,
                           const GeoReference& geo);
std::string write_wpl(const ExportPlan& plan, const UavWaypoints& uav, const GeoReference& geo);
std::string write_path_yaml(const ExportPlan& plan, const UavWaypoints& uav);
std::string write_hull_to_map_yaml(const GeoReference& geo);

/// A mission item shared by the qgc and wpl writers: MAV_CMD_NAV_WAYPOINT's seven parameters.
struct NavWaypoint {
  double hold_s = 0;
  double acceptance_m = 0;
  double pass_m = 0;
  double yaw_deg = 0;  ///< compass heading
  double lat = 0;
  double lon = 0;
  double rel_alt = 0;  ///< metres above the home position (frame 3, MAV_FRAME_GLOBAL_RELATIVE_ALT)
};
std::vector<NavWaypoint> nav_waypoints(const ExportPlan& plan, const UavWaypoints& uav,
                                       const GeoReference& geo);
/// The acceptance radius: a quarter cell, so a vehicle that accepts the waypoint is inside its
/// cell.
double acceptance_radius_m(const ExportPlan& plan);

}  // namespace hullinspect::io::detail
