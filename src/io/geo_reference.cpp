#include "hullinspect/io/geo_reference.hpp"

#include <fmt/format.h>
#include <GeographicLib/LocalCartesian.hpp>

#include <cmath>
#include <numbers>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"

namespace hullinspect::io {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr const char* kOriginParts[3] = {"LAT", "LON", "ALT"};
}  // namespace

struct GeoReference::Impl {
  GeographicLib::LocalCartesian local;
  double sin_psi;
  double cos_psi;
};

GeoReference::GeoReference(GeoPoint origin, double heading_deg)
    : origin_(origin), heading_deg_(heading_deg) {
  if (!(std::abs(origin.lat) <= kMaxLatitudeDeg) || !(std::abs(origin.lon) <= kMaxLongitudeDeg) ||
      !(origin.alt >= kMinOriginAltM && origin.alt <= kMaxOriginAltM)) {
    throw ParameterError(
        "origin", fmt::format("expects LAT,LON,ALT with LAT in [-90, 90], LON in "
                              "[-180, 180] and ALT in [{}, {}] m (got {},{},{})",
                              kMinOriginAltM, kMaxOriginAltM, origin.lat, origin.lon, origin.alt));
  }
  if (!(std::abs(heading_deg) <= kMaxHeadingDeg)) {
    throw ParameterError("heading",
                         fmt::format("expects degrees in [-360, 360] (got {})", heading_deg));
  }
  impl_ =
      std::make_unique<Impl>(Impl{GeographicLib::LocalCartesian(origin.lat, origin.lon, origin.alt),
                                  std::sin(heading_deg * kDeg), std::cos(heading_deg * kDeg)});
}

GeoReference::GeoReference(const GeoReference& other)
    : origin_(other.origin_),
      heading_deg_(other.heading_deg_),
      impl_(std::make_unique<Impl>(*other.impl_)) {}

GeoReference& GeoReference::operator=(const GeoReference& other) {
  if (this != &other) {
    origin_ = other.origin_;
    heading_deg_ = other.heading_deg_;
    impl_ = std::make_unique<Impl>(*other.impl_);
  }
  return *this;
}

GeoReference::~GeoReference() = default;

// The bow (+x) points along the heading ψ: (E, N) = (sin ψ, cos ψ); port (+y) is 90° to its left:
// (−cos ψ, sin ψ); up is up.
Enu GeoReference::to_enu(double x, double y, double z) const {
  const double s = impl_->sin_psi;
  const double c = impl_->cos_psi;
  return {x * s - y * c, x * c + y * s, z};
}

void GeoReference::from_enu(const Enu& e, double& x, double& y, double& z) const {
  const double s = impl_->sin_psi;
  const double c = impl_->cos_psi;
  x = e.east * s + e.north * c;
  y = -e.east * c + e.north * s;
  z = e.up;
}

GeoPoint GeoReference::to_wgs84(double x, double y, double z) const {
  const Enu e = to_enu(x, y, z);
  GeoPoint p;
  impl_->local.Reverse(e.east, e.north, e.up, p.lat, p.lon, p.alt);
  if (!(std::abs(p.lat) <= kMaxLatitudeDeg) || !(std::abs(p.lon) <= kMaxLongitudeDeg) ||
      !std::isfinite(p.alt)) {
    throw ParameterError("origin", fmt::format("the point ({}, {}, {}) m of the ship frame has no "
                                               "WGS-84 position (got {},{},{})",
                                               x, y, z, p.lat, p.lon, p.alt));
  }
  return p;
}

void GeoReference::from_wgs84(const GeoPoint& p, double& x, double& y, double& z) const {
  Enu e;
  impl_->local.Forward(p.lat, p.lon, p.alt, e.east, e.north, e.up);
  from_enu(e, x, y, z);
}

double GeoReference::compass_deg(double ship_yaw) const {
  double h = std::fmod(heading_deg_ - ship_yaw / kDeg, 360.0);
  if (h < 0) h += 360.0;
  if (h >= 360.0) h -= 360.0;
  return h;
}

double GeoReference::ship_yaw(double compass) const {
  return std::remainder((heading_deg_ - compass) * kDeg, 2 * std::numbers::pi);
}

double GeoReference::enu_rotation() const {
  return std::remainder((90.0 - heading_deg_) * kDeg, 2 * std::numbers::pi);
}

GeoPoint parse_geo_origin(const std::string& text) {
  const double limits[3][2] = {{-kMaxLatitudeDeg, kMaxLatitudeDeg},
                               {-kMaxLongitudeDeg, kMaxLongitudeDeg},
                               {kMinOriginAltM, kMaxOriginAltM}};
  double v[3] = {0, 0, 0};
  std::size_t at = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t end = i < 2 ? text.find(',', at) : text.size();
    constexpr const char* kExpected = "expects LAT,LON,ALT in degrees, degrees, metres";
    if (end == std::string::npos) {
      throw ParameterError("origin",
                           fmt::format("{} (got '{}')", kExpected, escape_for_message(text)));
    }
    try {
      v[i] = parse_real(std::string_view(text).substr(at, end - at), limits[i][0], limits[i][1]);
    } catch (const NumberError& e) {
      throw ParameterError("origin",
                           fmt::format("{}: {} {}", kExpected, kOriginParts[i], e.what()));
    }
    at = end + 1;
  }
  return {v[0], v[1], v[2]};
}

}  // namespace hullinspect::io
