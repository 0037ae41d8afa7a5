#pragma once
// Geo-referencing the ship frame (docs/export.md): the ship-frame origin at (lat, lon, alt) on the
// WGS-84 ellipsoid and the ship's heading ψ (degrees clockwise from north). ENU = R(ψ)·ship;
// WGS-84 from ENU through GeographicLib's LocalCartesian (a local tangent plane at the origin).

#include <memory>
#include <string>

namespace hullinspect::io {

/// The geo-reference's accepted ranges, the same for --origin/--heading and a --geo file: latitude
/// [−90, 90]°, longitude [−180, 180]°, height above the ellipsoid [−1 000, 10 000] m (sea level is
/// within ±110 m of it everywhere), heading [−360, 360]°.
inline constexpr double kMaxLatitudeDeg = 90;
inline constexpr double kMaxLongitudeDeg = 180;
inline constexpr double kMinOriginAltM = -1000;
inline constexpr double kMaxOriginAltM = 10000;
inline constexpr double kMaxHeadingDeg = 360;

struct Enu {
  double east = 0;
  double north = 0;
  double up = 0;
};

struct GeoPoint {
  double lat = 0;  ///< degrees
  double lon = 0;  ///< degrees
  double alt = 0;  ///< metres above the WGS-84 ellipsoid
};

class GeoReference {
 public:
  /// Throws ParameterError("origin" / "heading") when a value is outside the ranges above.
  GeoReference(GeoPoint origin, double heading_deg);
  GeoReference(const GeoReference& other);
  GeoReference& operator=(const GeoReference& other);
  ~GeoReference();

  const GeoPoint& origin() const { return origin_; }
  double heading_deg() const { return heading_deg_; }

  Enu to_enu(double x, double y, double z) const;
  /// Ship-frame coordinates of an ENU point (the inverse rotation).
  void from_enu(const Enu& enu, double& x, double& y, double& z) const;
  /// Throws ParameterError("origin") when the point has no finite WGS-84 coordinates (never for
  /// ship-frame points within ±world::kMaxShipFrameM).
  GeoPoint to_wgs84(double x, double y, double z) const;
  /// Ship-frame coordinates of a WGS-84 point (GeographicLib's inverse).
  void from_wgs84(const GeoPoint& p, double& x, double& y, double& z) const;

  /// A ship-frame yaw (radians, counter-clockwise from +x) as a compass heading in degrees
  /// clockwise from north, in [0, 360).
  double compass_deg(double ship_yaw) const;
  /// The inverse of compass_deg, in (−π, π].
  double ship_yaw(double compass_deg) const;
  /// The rotation hull → ENU about the up axis, radians counter-clockwise (= 90° − ψ).
  double enu_rotation() const;

 private:
  struct Impl;
  GeoPoint origin_;
  double heading_deg_;
  std::unique_ptr<Impl> impl_;
};

/// Parses "LAT,LON,ALT" (degrees, degrees, metres) for --origin with the number rules of
/// core/numbers.hpp and the ranges above; throws ParameterError("origin").
GeoPoint parse_geo_origin(const std::string& text);

}  // namespace hullinspect::io
