// The waypoints of a mission part on the Earth, shared by the qgc, wpl, litchi, dji-kmz and kml
// writers: positions, heights above the sortie's home point, compass headings and gimbal pitch.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "export_writers.hpp"

namespace hullinspect::io::detail {

double round_to(double v, double per_unit) {
  return std::round(v * per_unit) / per_unit;
}

double acceptance_radius_m(const ExportPlan& plan) {
  return plan.frame.spec().cell_m / 4.0;
}

GeoPoint home_point(const MissionPart& part, const GeoReference& geo) {
  const auto& h = part.sortie->home;
  return geo.to_wgs84(h.x, h.y, h.z);
}

namespace {
// The camera looks along −normal: its elevation above the horizontal, in degrees (0 for a
// vertical face, positive looking up under a flared hull).
double gimbal_pitch_deg(const ShipFrameSpec& spec, grid::Cell cell) {
  if (spec.normal.width() == 0 || !spec.normal.contains(cell)) return 0.0;
  const auto& n = spec.normal(cell.x, cell.y);
  return std::asin(std::clamp(-n[2], -1.0, 1.0)) * 180.0 / std::numbers::pi;
}
}  // namespace

std::vector<GeoWaypoint> geo_waypoints(const ExportPlan& plan, const MissionPart& part,
                                       const GeoReference& geo) {
  // Values are rounded as the text formats write them (1e-10 degrees, about 0.01 mm; 0.1 mm;
  // 0.001°), so every format carries the same numbers.
  const double home_alt = home_point(part, geo).alt;
  std::vector<GeoWaypoint> out;
  for (std::size_t i = 0; i < part.waypoints.size(); ++i) {
    const auto& w = part.waypoints[i];
    const auto& p = w.pose;
    GeoWaypoint g;
    // A later part's first waypoint is where the previous part ended: reached already.
    g.hold_s = i == 0 ? 0.0 : round_to(hold_seconds(plan, w, part.waypoints[i - 1]), 1e4);
    g.yaw_deg = round_to(geo.compass_deg(p.yaw), 1e3);
    if (g.yaw_deg >= 360) g.yaw_deg = 0;
    g.gimbal_pitch_deg =
        round_to(gimbal_pitch_deg(plan.frame.spec(), w.grid.cell), 1e3) + 0.0;  // no −0
    const GeoPoint e = geo.to_wgs84(p.x, p.y, p.z);
    g.lat = round_to(e.lat, 1e10);
    g.lon = round_to(e.lon, 1e10);
    g.rel_alt = round_to(e.alt - home_alt, 1e4);
    out.push_back(g);
  }
  return out;
}

}  // namespace hullinspect::io::detail
