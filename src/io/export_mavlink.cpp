// qgc (.plan JSON) and wpl (`QGC WPL 110` text): MAV_CMD_NAV_WAYPOINT (16) items in
// MAV_FRAME_GLOBAL_RELATIVE_ALT (3), home at the geo-reference origin.

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <cmath>

#include "export_writers.hpp"

namespace hullinspect::io::detail {

namespace {
constexpr int kNavWaypoint = 16;      // MAV_CMD_NAV_WAYPOINT
constexpr int kFrameRelativeAlt = 3;  // MAV_FRAME_GLOBAL_RELATIVE_ALT
constexpr int kFirmwarePx4 = 12;      // MAV_AUTOPILOT_PX4
constexpr int kVehicleQuadrotor = 2;  // MAV_TYPE_QUADROTOR
}  // namespace

namespace {
// Values are rounded as the wpl text writes them (1e-10 degrees, about 0.01 mm; 0.1 mm; 0.001°), so
// both formats carry the same numbers.
double round_to(double v, double per_unit) {
  return std::round(v * per_unit) / per_unit;
}
}  // namespace

double acceptance_radius_m(const ExportPlan& plan) {
  return plan.frame.spec().cell_m / 4.0;
}

std::vector<NavWaypoint> nav_waypoints(const ExportPlan& plan, const UavWaypoints& uav,
                                       const GeoReference& geo) {
  std::vector<NavWaypoint> items;
  const double speed = cruise_speed_mps(plan);
  for (std::size_t i = 0; i < uav.waypoints.size(); ++i) {
    const auto& w = uav.waypoints[i];
    const auto& p = w.pose;
    NavWaypoint n;
    n.hold_s = round_to(hold_seconds(w, uav.waypoints[i == 0 ? 0 : i - 1], speed), 1e4);
    n.acceptance_m = acceptance_radius_m(plan);
    n.yaw_deg = round_to(geo.compass_deg(p.yaw), 1e3);
    if (n.yaw_deg >= 360) n.yaw_deg = 0;
    const GeoPoint g = geo.to_wgs84(p.x, p.y, p.z);
    n.lat = round_to(g.lat, 1e10);
    n.lon = round_to(g.lon, 1e10);
    n.rel_alt = round_to(g.alt - geo.origin().alt, 1e4);
    items.push_back(n);
  }
  return items;
}

std::string write_qgc_plan(const ExportPlan& plan, const UavWaypoints& uav,
                           const GeoReference& geo) {
  using nlohmann::json;
  json items = json::array();
  int jump = 1;
  for (const auto& n : nav_waypoints(plan, uav, geo)) {
    items.push_back(
        {{"type", "SimpleItem"},
         {"command", kNavWaypoint},
         {"doJumpId", jump++},
         {"frame", kFrameRelativeAlt},
         {"autoContinue", true},
         {"AMSLAltAboveTerrain", nullptr},
         {"Altitude", n.rel_alt},
         {"AltitudeMode", 1},
         {"params", {n.hold_s, n.acceptance_m, n.pass_m, n.yaw_deg, n.lat, n.lon, n.rel_alt}}});
  }
  json polygons = json::array();
  // No-fly positions as exclusion polygons: the cell's extent along the hull and the band of
  // stand-offs in front of it (a geofence polygon is horizontal: it excludes every altitude).
  const auto& frame = plan.frame;
  const double half = frame.spec().cell_m / 2;
  for (const auto& c : plan.no_fly) {
    const auto near = frame.pose(c, 1);
    const auto far = frame.pose(c, 2);
    const double y0 = std::min(near.y, far.y) - half;
    const double y1 = std::max(near.y, far.y) + half;
    json ring = json::array();
    for (const auto& [x, y] : {std::pair{near.x - half, y0}, std::pair{near.x + half, y0},
                               std::pair{near.x + half, y1}, std::pair{near.x - half, y1}}) {
      const GeoPoint g = geo.to_wgs84(x, y, 0);
      ring.push_back({round_to(g.lat, 1e10), round_to(g.lon, 1e10)});
    }
    polygons.push_back({{"inclusion", false}, {"polygon", ring}, {"version", 1}});
  }
  const auto& o = geo.origin();
  json doc = {
      {"fileType", "Plan"},
      {"version", 1},
      {"groundStation", "QGroundControl"},
      {"mission",
       {{"version", 2},
        {"firmwareType", kFirmwarePx4},
        {"vehicleType", kVehicleQuadrotor},
        {"cruiseSpeed", cruise_speed_mps(plan)},
        {"hoverSpeed", cruise_speed_mps(plan)},
        {"plannedHomePosition", {o.lat, o.lon, o.alt}},
        {"items", items}}},
      {"geoFence", {{"version", 2}, {"polygons", polygons}, {"circles", json::array()}}},
      {"rallyPoints", {{"version", 2}, {"points", json::array()}}},
  };
  return doc.dump(1, '\t') + "\n";
}

std::string write_wpl(const ExportPlan& plan, const UavWaypoints& uav, const GeoReference& geo) {
  // INDEX CURRENT FRAME COMMAND P1 P2 P3 P4 LAT LON ALT AUTOCONTINUE; line 0 is home (frame 0,
  // AMSL).
  const auto& o = geo.origin();
  std::string out = "QGC WPL 110\n";
  out += fmt::format("0\t1\t0\t{}\t0\t0\t0\t0\t{:.10f}\t{:.10f}\t{:.4f}\t1\n", kNavWaypoint, o.lat,
                     o.lon, o.alt);
  int index = 1;
  for (const auto& n : nav_waypoints(plan, uav, geo)) {
    out +=
        fmt::format("{}\t0\t{}\t{}\t{:.4f}\t{:.4f}\t{:.4f}\t{:.3f}\t{:.10f}\t{:.10f}\t{:.4f}\t1\n",
                    index++, kFrameRelativeAlt, kNavWaypoint, n.hold_s, n.acceptance_m, n.pass_m,
                    n.yaw_deg, n.lat, n.lon, n.rel_alt);
  }
  return out;
}

}  // namespace hullinspect::io::detail
