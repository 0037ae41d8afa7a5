#pragma once
// A geo-reference from two surveyed points (docs/export.md, "Two surveyed points"): a crew
// measures two points of the hull (stern and bow at the waterline, say) with a GNSS receiver; with
// their ship-frame coordinates from the ship's drawings, the origin and the heading follow.

#include "hullinspect/io/geo_reference.hpp"

namespace hullinspect::io {

/// A point known both in the ship frame (metres) and on the WGS-84 ellipsoid.
struct SurveyedPoint {
  double x = 0;  ///< along the hull, forward
  double y = 0;  ///< to port
  double z = 0;  ///< up
  GeoPoint at;
};

/// The shortest horizontal distance between the two points that fixes a heading, metres.
inline constexpr double kMinSurveyBaselineM = 1.0;
/// The default tolerance between the points' distance on the ship and on the ground, metres.
inline constexpr double kDefaultSurveyToleranceM = 0.5;

/// The geo-reference that puts both points where they were surveyed: the heading turns the ship's
/// horizontal direction from a to b onto the ground's, and the origin lies where a's ship-frame
/// offset leads back from a. Throws ParameterError("geo", …) when the points are less than
/// kMinSurveyBaselineM apart horizontally on the ship, or when their horizontal or vertical
/// distance on the ground differs from the ship's by more than `tolerance_m`.
GeoReference geo_from_survey(const SurveyedPoint& a, const SurveyedPoint& b, double tolerance_m);

}  // namespace hullinspect::io
