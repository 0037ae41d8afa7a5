// A geo-reference from two surveyed points (docs/export.md): a known reference → two points →
// the same reference, and the degenerate surveys refused.

#include "hullinspect/io/geo_survey.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::io {
namespace {

SurveyedPoint surveyed(const GeoReference& ref, double x, double y, double z) {
  return {x, y, z, ref.to_wgs84(x, y, z)};
}

TEST(GeoSurvey, TwoPointsGiveTheReferenceBack) {
  for (const double heading : {0.0, 37.5, 90.0, 181.25, 359.0}) {
    const GeoReference ref({53.54, 9.97, 3.0}, heading);
    // Stern and bow at the waterline of a 160 m hull, one on a side plane 27 m to port.
    for (const double y : {0.0, 27.25}) {
      const auto a = surveyed(ref, -6.7, y, 1.0);
      const auto b = surveyed(ref, 152.0, y, 1.5);
      const GeoReference got = geo_from_survey(a, b, kDefaultSurveyToleranceM);
      EXPECT_NEAR(std::remainder(got.heading_deg() - heading, 360.0), 0.0, 1e-6) << heading;
      EXPECT_NEAR(got.origin().lat, 53.54, 1e-8);  // about a millimetre
      EXPECT_NEAR(got.origin().lon, 9.97, 1e-8);
      EXPECT_NEAR(got.origin().alt, 3.0, 5e-3);
      // Every point of the ship lands where the original reference puts it.
      const GeoPoint p = got.to_wgs84(80, y, 10);
      const GeoPoint q = ref.to_wgs84(80, y, 10);
      EXPECT_NEAR(p.lat, q.lat, 1e-8);
      EXPECT_NEAR(p.lon, q.lon, 1e-8);
    }
  }
}

TEST(GeoSurvey, AnObliqueBaselineWorksToo) {
  // Points not along the bow axis: the heading comes from the ship's own direction a → b.
  const GeoReference ref({-33.9, 18.4, 0.0}, 250.0);
  const GeoReference got =
      geo_from_survey(surveyed(ref, 10, -5, 0), surveyed(ref, 40, 25, 2), 0.01);
  EXPECT_NEAR(got.heading_deg(), 250.0, 1e-6);
  EXPECT_NEAR(got.origin().lat, -33.9, 1e-8);
  EXPECT_NEAR(got.origin().lon, 18.4, 1e-8);
}

std::string refusal(const SurveyedPoint& a, const SurveyedPoint& b, double tolerance) {
  try {
    geo_from_survey(a, b, tolerance);
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.name(), "geo");
    return e.problem();
  }
  return "accepted";
}

TEST(GeoSurvey, DegenerateSurveysAreRefused) {
  const GeoReference ref({53.54, 9.97, 3.0}, 30.0);
  const auto a = surveyed(ref, 0, 0, 1);
  EXPECT_EQ(refusal(a, a, 0.5),
            "the two surveyed points are 0.000 m apart horizontally on the ship; the heading "
            "needs at least 1 m (survey two distant points, e.g. the stern and the bow)");
  // The same GNSS fix for a point given 2 m further aft: 2 m off on the ground.
  auto b = surveyed(ref, 100, 0, 1);
  b.x = 102;
  EXPECT_EQ(refusal(a, b, 0.5),
            "the surveyed points are 102.000 m apart horizontally on the ship but 100.000 m on "
            "the ground (tolerance 0.5 m): check their coordinates");
  EXPECT_EQ(refusal(a, b, 2.5), "accepted");
  auto c = surveyed(ref, 100, 0, 1);
  c.z = 4;
  EXPECT_EQ(refusal(a, c, 0.5),
            "the second surveyed point is 3.000 m above the first on the ship but 0.000 m on "
            "the ground (tolerance 0.5 m): check their heights");
}

}  // namespace
}  // namespace hullinspect::io
