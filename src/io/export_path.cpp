// path: YAML mirroring ROS 2 nav_msgs/Path in the frame `hull` (the ship frame, REP-103 axes:
// x forward, y left = port, z up), and geometry_msgs/TransformStamped map → hull.

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "export_writers.hpp"

namespace hullinspect::io::detail {

namespace {
// A builtin_interfaces/Time: whole seconds (floor, so negative times stay ordered) and the
// nanoseconds past them.
std::string stamp(double seconds) {
  const auto ns = static_cast<long long>(std::llround(seconds * 1e9));
  const long long sec = ns >= 0 ? ns / 1000000000 : -((-ns + 999999999) / 1000000000);
  return fmt::format("{{sec: {}, nanosec: {}}}", sec, ns - sec * 1000000000);
}
}  // namespace

std::string write_path_yaml(const ExportPlan& plan, const MissionPart& part) {
  std::string out = fmt::format(
      "# nav_msgs/Path of UAV {}: stamps are seconds since {}; frame hull = ship frame\n"
      "header:\n  stamp: {}\n  frame_id: hull\nposes:\n",
      part.sortie->uav,
      part.sortie->flown        ? "the mission's start (its first take-off)"
      : part.sortie->given_site ? "the plan's start (negative before it)"
                                : "take-off",
      stamp(0));
  for (const auto& w : part.waypoints) {
    const auto& p = w.pose;
    out += fmt::format(
        "  - header: {{stamp: {}, frame_id: hull}}  # {} plane {}\n"
        "    pose:\n"
        "      position: {{x: {:.4f}, y: {:.4f}, z: {:.4f}}}\n"
        "      orientation: {{x: 0.0, y: 0.0, z: {:.9f}, w: {:.9f}}}\n",
        stamp(plan.seconds(w.grid.t)), to_string(w.grid.action), w.grid.z, p.x, p.y, p.z,
        std::sin(p.yaw / 2), std::cos(p.yaw / 2));
  }
  return out;
}

std::string write_hull_to_map_yaml(const GeoReference& geo) {
  const double r = geo.enu_rotation();
  const auto& o = geo.origin();
  return fmt::format(
      "# geometry_msgs/TransformStamped: the static transform from map (ENU at the origin below) "
      "to\n"
      "# hull (the ship frame); hull's origin is at lat {:.10f}, lon {:.10f}, alt {:.4f} m "
      "(WGS-84),\n"
      "# heading {} deg. Publish it with:\n"
      "#   ros2 run tf2_ros static_transform_publisher --yaw {:.9f} --frame-id map "
      "--child-frame-id hull\n"
      "header:\n  stamp: {{sec: 0, nanosec: 0}}\n  frame_id: map\n"
      "child_frame_id: hull\n"
      "transform:\n"
      "  translation: {{x: 0.0, y: 0.0, z: 0.0}}\n"
      "  rotation: {{x: 0.0, y: 0.0, z: {:.9f}, w: {:.9f}}}\n",
      o.lat, o.lon, o.alt, geo.heading_deg(), r, std::sin(r / 2), std::cos(r / 2));
}

}  // namespace hullinspect::io::detail
