#pragma once
// Bounds of the ship frame every export is derived in (docs/export.md): a cell side in
// [1 mm, 1 km] and every coordinate (the origin, the side plane, a depth, each waypoint) within
// ±100 km of the ship-frame origin, so waypoints stay finite and distinct through every conversion
// (hold times divide by the cell side; WGS-84 conversions assume a local tangent plane).

namespace hullinspect::world {

inline constexpr double kMinCellSizeM = 1e-3;
inline constexpr double kMaxCellSizeM = 1e3;
inline constexpr double kMaxShipFrameM = 1e5;

}  // namespace hullinspect::world
