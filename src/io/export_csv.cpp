// csv: one row per waypoint in the ship frame, plus ENU and WGS-84 columns when geo-referenced.

#include <fmt/format.h>

#include <numbers>

#include "export_writers.hpp"

namespace hullinspect::io::detail {

std::string write_csv(const ExportPlan& plan, const MissionPart& part,
                      const std::optional<GeoReference>& geo) {
  std::string out = "index,t_s,x_m,y_m,z_m,yaw_deg,plane,action,duration_s,cell_x,cell_y";
  if (geo) out += ",east_m,north_m,up_m,lat_deg,lon_deg,alt_m,heading_deg";
  out += "\n";
  int index = 0;
  for (const auto& w : part.waypoints) {
    const auto& p = w.pose;
    out += fmt::format("{},{},{:.4f},{:.4f},{:.4f},{:.3f},{},{},{},{},{}", index++,
                       plan.seconds(w.grid.t), p.x, p.y, p.z, p.yaw * 180.0 / std::numbers::pi,
                       w.grid.z, to_string(w.grid.action), plan.seconds(w.grid.duration),
                       w.grid.cell.x, w.grid.cell.y);
    if (geo) {
      const Enu e = geo->to_enu(p.x, p.y, p.z);
      const GeoPoint g = geo->to_wgs84(p.x, p.y, p.z);
      out += fmt::format(",{:.4f},{:.4f},{:.4f},{:.10f},{:.10f},{:.4f},{:.3f}", e.east, e.north,
                         e.up, g.lat, g.lon, g.alt, geo->compass_deg(p.yaw));
    }
    out += "\n";
  }
  return out;
}

}  // namespace hullinspect::io::detail
