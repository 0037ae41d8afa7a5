#include "hullinspect/io/geo_reference.hpp"

#include <fmt/format.h>
#include <GeographicLib/LocalCartesian.hpp>

#include <charconv>
#include <cmath>
#include <numbers>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::io {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}  // namespace

struct GeoReference::Impl {
  GeographicLib::LocalCartesian local;
  double sin_psi;
  double cos_psi;
};

GeoReference::GeoReference(GeoPoint origin, double heading_deg)
    : origin_(origin), heading_deg_(heading_deg) {
  if (!(origin.lat >= -90 && origin.lat <= 90) || !(origin.lon >= -180 && origin.lon <= 180) ||
      !std::isfinite(origin.alt)) {
    throw ParameterError("origin",
                         fmt::format("expects LAT,LON,ALT with LAT in [-90, 90] and LON in "
                                     "[-180, 180] (got {},{},{})",
                                     origin.lat, origin.lon, origin.alt));
  }
  if (!std::isfinite(heading_deg))
    throw ParameterError("heading", "expects a finite number of degrees");
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
  double v[3] = {0, 0, 0};
  std::size_t at = 0;
  for (int i = 0; i < 3; ++i) {
    const std::size_t end = i < 2 ? text.find(',', at) : text.size();
    const char* first = text.data() + at;
    const char* last = text.data() + (end == std::string::npos ? text.size() : end);
    const auto [ptr, ec] = std::from_chars(first, last, v[i]);
    if (end == std::string::npos || ec != std::errc() || ptr != last || first == last ||
        !std::isfinite(v[i])) {
      throw ParameterError(
          "origin",
          fmt::format("expects LAT,LON,ALT in degrees, degrees, metres (got '{}')", text));
    }
    at = end + 1;
  }
  return {v[0], v[1], v[2]};
}

}  // namespace hullinspect::io
