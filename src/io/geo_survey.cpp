#include "hullinspect/io/geo_survey.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::io {

GeoReference geo_from_survey(const SurveyedPoint& a, const SurveyedPoint& b, double tolerance_m) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double ship_horizontal = std::hypot(dx, dy);
  if (!(ship_horizontal >= kMinSurveyBaselineM)) {
    throw ParameterError(
        "geo", fmt::format("the two surveyed points are {:.3f} m apart horizontally on the ship; "
                           "the heading needs at least {} m (survey two distant points, e.g. the "
                           "stern and the bow)",
                           ship_horizontal, kMinSurveyBaselineM));
  }
  // b in a local frame at a with heading 0, where ship x is north and ship y is west.
  const GeoReference at_a(a.at, 0.0);
  double north = 0, west = 0, up = 0;
  at_a.from_wgs84(b.at, north, west, up);
  const double east = -west;
  const double ground_horizontal = std::hypot(east, north);
  if (!(std::abs(ground_horizontal - ship_horizontal) <= tolerance_m)) {
    throw ParameterError(
        "geo", fmt::format("the surveyed points are {:.3f} m apart horizontally on the ship but "
                           "{:.3f} m on the ground (tolerance {} m): check their coordinates",
                           ship_horizontal, ground_horizontal, tolerance_m));
  }
  const double dz = b.z - a.z;
  if (!(std::abs(up - dz) <= tolerance_m)) {
    throw ParameterError(
        "geo", fmt::format("the second surveyed point is {:.3f} m above the first on the ship but "
                           "{:.3f} m on the ground (tolerance {} m): check their heights",
                           dz, up, tolerance_m));
  }
  // A ship direction at angle φ counter-clockwise from the bow has the compass bearing ψ − φ, so
  // ψ = bearing(a → b on the ground) + φ(a → b on the ship). North turns across a ship's length
  // (by about 10⁻³° per 100 m at 53° N), so ψ and the origin are solved in the tangent plane at
  // the origin itself: from a guess (a's plane), each round measures both points in the plane at
  // the last origin and moves the origin to where a's ship-frame offset leads back from a; the
  // error shrinks by the ship's length over the earth's radius each round.
  constexpr double kDeg = 180.0 / std::numbers::pi;
  const double phi = std::atan2(dy, dx);
  GeoPoint origin = a.at;
  double heading = 0;
  for (int round = 0; round < 4; ++round) {
    const GeoReference plane(origin, 0.0);  // ship x = north, ship y = west
    double an = 0, aw = 0, au = 0, bn = 0, bw = 0, bu = 0;
    plane.from_wgs84(a.at, an, aw, au);
    plane.from_wgs84(b.at, bn, bw, bu);
    heading = std::fmod((std::atan2(aw - bw, bn - an) + phi) * kDeg + 720.0, 360.0);
    const Enu ra = GeoReference(origin, heading).to_enu(a.x, a.y, a.z);
    // The origin's ENU in this plane is a's minus R(ψ)·a; back to the plane's (north, west, up).
    const double e = -aw - ra.east;
    const double n = an - ra.north;
    const double u = au - ra.up;
    origin = plane.to_wgs84(n, -e, u);
  }
  return GeoReference(origin, heading);
}

}  // namespace hullinspect::io
