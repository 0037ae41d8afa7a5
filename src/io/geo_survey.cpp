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
  // ψ = bearing(a → b on the ground) + φ(a → b on the ship).
  constexpr double kDeg = 180.0 / std::numbers::pi;
  double heading = (std::atan2(east, north) + std::atan2(dy, dx)) * kDeg;
  heading = std::fmod(heading + 720.0, 360.0);
  // The origin: a's ship-frame offset taken back from a, in the tangent plane at a (over a ship's
  // length the plane departs from the ellipsoid by millimetres).
  const GeoReference from_a(a.at, heading);
  return GeoReference(from_a.to_wgs84(-a.x, -a.y, -a.z), heading);
}

}  // namespace hullinspect::io
