// qgc (.plan JSON) and wpl (`QGC WPL 110` text): complete MAVLink missions. Each file holds, in
// order: NAV_TAKEOFF at the sortie's home point (first part only), DO_CHANGE_SPEED, the gimbal
// pitch, the camera's distance trigger from the plan's start to its end, the waypoints (with
// ArduPilot's CONDITION_YAW where the heading changes), then LAND at the home point or RTL
// (last part only). Navigation items are in MAV_FRAME_GLOBAL_RELATIVE_ALT: heights above home.

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <limits>

#include "export_writers.hpp"

namespace hullinspect::io::detail {

namespace {
constexpr int kNavWaypoint = 16;         // MAV_CMD_NAV_WAYPOINT
constexpr int kNavRtl = 20;              // MAV_CMD_NAV_RETURN_TO_LAUNCH
constexpr int kNavLand = 21;             // MAV_CMD_NAV_LAND
constexpr int kNavTakeoff = 22;          // MAV_CMD_NAV_TAKEOFF
constexpr int kConditionYaw = 115;       // MAV_CMD_CONDITION_YAW
constexpr int kDoChangeSpeed = 178;      // MAV_CMD_DO_CHANGE_SPEED
constexpr int kDoMountControl = 205;     // MAV_CMD_DO_MOUNT_CONTROL (ArduPilot's gimbal)
constexpr int kDoCamTriggDist = 206;     // MAV_CMD_DO_SET_CAM_TRIGG_DIST
constexpr int kDoGimbalPitchYaw = 1000;  // MAV_CMD_DO_GIMBAL_MANAGER_PITCHYAW (PX4's gimbal)
constexpr int kFrameMission = 2;         // MAV_FRAME_MISSION (commands without a position)
constexpr int kFrameRelativeAlt = 3;     // MAV_FRAME_GLOBAL_RELATIVE_ALT
constexpr int kFirmwarePx4 = 12;         // MAV_AUTOPILOT_PX4
constexpr int kFirmwareArduPilot = 3;    // MAV_AUTOPILOT_ARDUPILOTMEGA
constexpr int kVehicleQuadrotor = 2;     // MAV_TYPE_QUADROTOR
constexpr int kMountModeTargeting = 2;   // MAV_MOUNT_MODE_MAVLINK_TARGETING
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct MissionItem {
  int command = 0;
  int frame = kFrameMission;
  std::array<double, 7> params{};
};

MissionItem gimbal_item(Firmware firmware, double pitch_deg) {
  if (firmware == Firmware::kArduPilot) {
    return {kDoMountControl, kFrameMission, {pitch_deg, 0, 0, 0, 0, 0, kMountModeTargeting}};
  }
  return {kDoGimbalPitchYaw, kFrameMission, {pitch_deg, 0, kNaN, kNaN, 0, 0, 0}};
}

std::vector<MissionItem> mission_items(const ExportPlan& plan, const MissionPart& part,
                                       const GeoReference& geo, const ExportSettings& settings) {
  const auto points = geo_waypoints(plan, part, geo);
  GeoPoint home = home_point(part, geo);
  home.lat = round_to(home.lat, 1e10);  // as the waypoints' positions
  home.lon = round_to(home.lon, 1e10);
  const auto& sortie = *part.sortie;
  // The leg leaving the sortie's waypoint s photographs when it is a leg of the plan: not on the
  // flights between the launch site and the hull.
  const auto photographing = [&](std::size_t s) {
    return s >= sortie.plan_begin() && s + 1 < sortie.plan_end();
  };
  const bool ardupilot = settings.firmware == Firmware::kArduPilot;

  std::vector<MissionItem> items;
  if (part.takes_off() && !points.empty()) {
    items.push_back(
        {kNavTakeoff,
         kFrameRelativeAlt,
         {0, 0, 0, points.front().yaw_deg, home.lat, home.lon, points.front().rel_alt}});
  }
  const double speed = cruise_speed_mps(plan);
  items.push_back({kDoChangeSpeed, kFrameMission, {1, speed, -1, 0, 0, 0, 0}});
  double pitch = kNaN;
  double yaw = kNaN;
  bool triggering = false;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    const std::size_t s = part.offset() + i;
    if (!(std::abs(p.gimbal_pitch_deg - pitch) < 0.5)) {  // also when pitch is still NaN
      items.push_back(gimbal_item(settings.firmware, p.gimbal_pitch_deg));
      pitch = p.gimbal_pitch_deg;
    }
    if (ardupilot && p.yaw_deg != yaw) {  // a copter ignores NAV_WAYPOINT's yaw
      items.push_back({kConditionYaw, kFrameMission, {p.yaw_deg, 0, 0, 0, 0, 0, 0}});
    }
    yaw = p.yaw_deg;
    items.push_back({kNavWaypoint,
                     kFrameRelativeAlt,
                     {p.hold_s, acceptance_radius_m(plan), 0, p.yaw_deg, p.lat, p.lon, p.rel_alt}});
    // Photos on the legs from the plan's first waypoint to its last: one every cell.
    if (photographing(s) != triggering) {
      triggering = !triggering;
      items.push_back(
          {kDoCamTriggDist,
           kFrameMission,
           {triggering ? photo_distance_m(plan) : 0, 0, triggering ? 1.0 : 0.0, 0, 0, 0, 0}});
    }
  }
  if (triggering) items.push_back({kDoCamTriggDist, kFrameMission, {0, 0, 0, 0, 0, 0, 0}});
  if (part.lands()) {
    if (settings.finish == FinishAction::kRtl) {
      items.push_back({kNavRtl, kFrameMission, {0, 0, 0, 0, 0, 0, 0}});
    } else {
      // Land facing as the last waypoint did: an explicit yaw, so no file needs NaN's meaning
      // ("keep the current heading"), which a WPL file cannot write (its unset value is 0).
      const double yaw_deg = points.empty() ? 0.0 : points.back().yaw_deg;
      items.push_back({kNavLand, kFrameRelativeAlt, {0, 0, 0, yaw_deg, home.lat, home.lon, 0}});
    }
  }
  return items;
}

// The home point with the height MAVLink's absolute frames mean, above mean sea level, when the
// geoid's height is known; else its ellipsoidal height (docs/export.md, "Altitudes").
GeoPoint home_above_sea_level(const MissionPart& part, const GeoReference& geo,
                              const ExportSettings& settings) {
  GeoPoint home = home_point(part, geo);
  if (settings.geoid_height_m) home.alt -= *settings.geoid_height_m;
  return home;
}

nlohmann::json param_json(double v) {
  return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v);
}

}  // namespace

std::string write_qgc_plan(const ExportPlan& plan, const MissionPart& part, const GeoReference& geo,
                           const ExportSettings& settings) {
  using nlohmann::json;
  json items = json::array();
  int jump = 1;
  for (const auto& m : mission_items(plan, part, geo, settings)) {
    json params = json::array();
    for (double v : m.params) params.push_back(param_json(v));
    json item = {{"type", "SimpleItem"}, {"command", m.command}, {"doJumpId", jump++},
                 {"frame", m.frame},     {"autoContinue", true}, {"params", params}};
    if (m.frame == kFrameRelativeAlt) {
      item["AMSLAltAboveTerrain"] = nullptr;
      item["Altitude"] = m.params[6];
      item["AltitudeMode"] = 1;  // relative to home
    }
    items.push_back(item);
  }
  // No geofence: a no-fly position is a vertical obstacle in front of the hull, and a QGC fence
  // polygon is horizontal (it would also forbid the legal flight above or below it).
  const GeoPoint home = home_above_sea_level(part, geo, settings);
  json doc = {
      {"fileType", "Plan"},
      {"version", 1},
      {"groundStation", "QGroundControl"},
      {"mission",
       {{"version", 2},
        {"firmwareType",
         settings.firmware == Firmware::kArduPilot ? kFirmwareArduPilot : kFirmwarePx4},
        {"vehicleType", kVehicleQuadrotor},
        {"cruiseSpeed", cruise_speed_mps(plan)},
        {"hoverSpeed", cruise_speed_mps(plan)},
        {"plannedHomePosition",
         {round_to(home.lat, 1e10), round_to(home.lon, 1e10), round_to(home.alt, 1e4)}},
        {"items", items}}},
      {"geoFence", {{"version", 2}, {"polygons", json::array()}, {"circles", json::array()}}},
      {"rallyPoints", {{"version", 2}, {"points", json::array()}}},
  };
  return doc.dump(1, '\t') + "\n";
}

std::string write_wpl(const ExportPlan& plan, const MissionPart& part, const GeoReference& geo,
                      const ExportSettings& settings) {
  // INDEX CURRENT FRAME COMMAND P1 P2 P3 P4 LAT LON ALT AUTOCONTINUE; line 0 is home (frame 0,
  // absolute: above mean sea level when the geoid's height is given, else ellipsoidal).
  const GeoPoint home = home_above_sea_level(part, geo, settings);
  std::string out = "QGC WPL 110\n";
  out += fmt::format("0\t1\t0\t{}\t0\t0\t0\t0\t{:.10f}\t{:.10f}\t{:.4f}\t1\n", kNavWaypoint,
                     home.lat, home.lon, home.alt);
  int index = 1;
  // A parameter the command leaves unset (NaN in the .plan's items) is written 0, the format's
  // value for an unused parameter.
  const auto number = [](double v, int digits) {
    return fmt::format("{:.{}f}", std::isnan(v) ? 0.0 : v, digits);
  };
  for (const auto& m : mission_items(plan, part, geo, settings)) {
    const auto& p = m.params;
    out += fmt::format("{}\t0\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t1\n", index++, m.frame,
                       m.command, number(p[0], 4), number(p[1], 4), number(p[2], 4),
                       number(p[3], 3), number(p[4], 10), number(p[5], 10), number(p[6], 4));
  }
  return out;
}

}  // namespace hullinspect::io::detail
