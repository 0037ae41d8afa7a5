#pragma once
// The per-format writers behind io::export_files (one mission part, one file each; KML one file
// for the whole fleet).

#include <optional>
#include <string>
#include <vector>

#include "hullinspect/io/export.hpp"

namespace hullinspect::io::detail {

std::string write_csv(const ExportPlan& plan, const MissionPart& part,
                      const std::optional<GeoReference>& geo);
std::string write_qgc_plan(const ExportPlan& plan, const MissionPart& part, const GeoReference& geo,
                           const ExportSettings& settings);
std::string write_wpl(const ExportPlan& plan, const MissionPart& part, const GeoReference& geo,
                      const ExportSettings& settings);
std::string write_path_yaml(const ExportPlan& plan, const MissionPart& part);
std::string write_hull_to_map_yaml(const GeoReference& geo);
std::string write_litchi(const ExportPlan& plan, const MissionPart& part, const GeoReference& geo);
std::string write_dji_kmz(const ExportPlan& plan, const MissionPart& part, const GeoReference& geo,
                          const ExportSettings& settings);
std::string write_kml(const ExportPlan& plan, const std::vector<Sortie>& sorties,
                      const GeoReference& geo);

/// A waypoint placed on the Earth, shared by the geo formats.
struct GeoWaypoint {
  double hold_s = 0;            ///< time to wait on arrival
  double yaw_deg = 0;           ///< compass heading the camera faces, [0, 360)
  double gimbal_pitch_deg = 0;  ///< 0 = horizontal; negative looks down
  double lat = 0;
  double lon = 0;
  double rel_alt = 0;  ///< metres above the sortie's home point
};
std::vector<GeoWaypoint> geo_waypoints(const ExportPlan& plan, const MissionPart& part,
                                       const GeoReference& geo);
/// The sortie's home point (take-off and landing) on the Earth; alt is the ellipsoidal height.
GeoPoint home_point(const MissionPart& part, const GeoReference& geo);
/// The acceptance radius: a quarter cell, so a vehicle that accepts the waypoint is inside its
/// cell.
double acceptance_radius_m(const ExportPlan& plan);
/// Rounds as the text formats write numbers (per_unit = 1e10 for 1e-10 degrees).
double round_to(double v, double per_unit);

}  // namespace hullinspect::io::detail
