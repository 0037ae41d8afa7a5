// litchi: Litchi's CSV mission (one row a waypoint). Altitudes are above the take-off point
// (altitudemode 0), headings compass degrees, the gimbal pitch interpolated between waypoints,
// holds as "stay" actions, photos every cell on the legs of the plan (photo_distinterval).

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "export_writers.hpp"

namespace hullinspect::io::detail {

namespace {
constexpr int kActions = 15;           // action pairs a Litchi row holds
constexpr int kActionStay = 0;         // stay for N milliseconds
constexpr int kMaxStayMs = 32000;      // the longest stay one action may ask (Litchi: 32 s)
constexpr int kGimbalInterpolate = 2;  // gimbalmode: interpolate the pitch between waypoints
}  // namespace

std::string write_litchi(const ExportPlan& plan, const MissionPart& part, const GeoReference& geo) {
  std::string out =
      "latitude,longitude,altitude(m),heading(deg),curvesize(m),rotationdir,gimbalmode,"
      "gimbalpitchangle";
  for (int a = 1; a <= kActions; ++a) out += fmt::format(",actiontype{0},actionparam{0}", a);
  out +=
      ",altitudemode,speed(m/s),poi_latitude,poi_longitude,poi_altitude(m),poi_altitudemode,"
      "photo_timeinterval,photo_distinterval\n";
  const auto points = geo_waypoints(plan, part, geo);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    out += fmt::format("{:.10f},{:.10f},{:.4f},{:.3f},0,0,{},{:.3f}", p.lat, p.lon, p.rel_alt,
                       p.yaw_deg, kGimbalInterpolate, p.gimbal_pitch_deg);
    int ms = static_cast<int>(std::lround(p.hold_s * 1000));
    for (int a = 0; a < kActions; ++a) {
      if (ms > 0 && a < kActions) {
        const int stay = std::min(ms, kMaxStayMs);
        out += fmt::format(",{},{}", kActionStay, stay);
        ms -= stay;
      } else {
        out += ",-1,0";
      }
    }
    // The leg leaving waypoint s photographs when it is a leg of the plan.
    const std::size_t s = part.offset() + i;
    const bool photo = s >= part.sortie->plan_begin() && s + 1 < part.sortie->plan_end();
    out += fmt::format(",0,{:.4f},0,0,0,0,-1,{}\n", cruise_speed_mps(plan),
                       photo ? fmt::format("{:.4f}", photo_distance_m(plan)) : std::string("-1"));
  }
  return out;
}

}  // namespace hullinspect::io::detail
