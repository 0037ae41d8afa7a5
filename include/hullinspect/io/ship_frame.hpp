#pragma once
// Grid positions to the ship frame (docs/export.md, docs/model.md "Frames and exports"):
// x forward (stern → bow), y to port, z up, metres — REP-103 axes.
//   X = X0 + (x + ½)·cell,  Z = Z0 + (y + ½)·cell,  Y = Ys ± (ζ_z + depth(x, y))
// with + when the port side is inspected, − for starboard, ζ_z = s_z·cell / (2·tan(θ/2)), and
// depth 0 for a hull without a mesh. The camera faces the surface: yaw along −normal.
// An unrolled hull (both sides in one grid, docs/hulls.md "The whole hull") has no side plane:
// each cell carries its ship-frame surface point S and outward normal n, and a UAV stands at
// S + ζ_z·n looking along −n.

#include <nlohmann/json.hpp>

#include <array>
#include <string>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/world/mission_params.hpp"

namespace hullinspect::io {

/// A UAV pose in the ship frame: position (m) and yaw (radians, counter-clockwise from +x about
/// +z, so 0 looks toward the bow and +π/2 toward port).
struct ShipPose {
  double x = 0;
  double y = 0;
  double z = 0;
  double yaw = 0;
};

/// Which side of the ship the hull grid shows; kBoth: the unrolled hull.
enum class HullSide { kPort, kStarboard, kBoth };

/// Everything that places the grid in the ship frame.
struct ShipFrameSpec {
  double cell_m = world::MissionParams{}.cell_size_m;  ///< cell side
  int s1 = world::MissionParams{}.s1;                  ///< footprint sides (cells) at z = 1, 2
  int s2 = world::MissionParams{}.s2;
  double theta_deg = world::MissionParams{}.theta_deg;  ///< camera aperture
  double x0 = 0;                                        ///< X of the grid's left (stern) edge
  double z0 = 0;                                        ///< Z of the grid's bottom edge
  double ys = 0;                                        ///< Y of the side plane
  HullSide side = HullSide::kStarboard;  ///< as world::HullGeometry; a plain mask is starboard
  grid::Grid<double> depth;              ///< per cell, metres; empty = 0 everywhere
  /// Per cell outward unit normal (ship frame); empty = the side's normal (0, ±1, 0).
  grid::Grid<std::array<double, 3>> normal;
  /// Unrolled hulls only (side kBoth): per cell the ship-frame surface point the UAV stands off
  /// from; x0 is then the arc length of column 0's left edge and ys the centre plane.
  grid::Grid<std::array<double, 3>> surface;
  /// The file these numbers came from (a trace, a hull), named by errors.
  std::string source = "trace";
};

class ShipFrame {
 public:
  explicit ShipFrame(ShipFrameSpec spec);

  /// The pose of a UAV at cell (x, y) on plane z ∈ {1, 2}. Throws InputError(spec.source) when a
  /// coordinate is not finite or lies beyond ±world::kMaxShipFrameM (a cell size, θ or origin
  /// that no export can represent), so no writer ever sees such a number.
  ShipPose pose(grid::Cell cell, int z) const;
  /// The hull's surface at the centre of `cell` (no stand-off): x, y, z in metres. The cell must
  /// lie on the grid (unrolled: throws InputError(spec.source) when it does not).
  std::array<double, 3> surface_point(grid::Cell cell) const;
  /// ζ_z in metres.
  double standoff_m(int z) const;
  /// depth(x, y) in metres (0 without a mesh).
  double depth_m(grid::Cell cell) const;
  /// True when a leg from a to b stays at one stand-off distance and yaw (same depth and normal).
  bool same_surface(grid::Cell a, grid::Cell b) const;

  /// The cell whose centre is nearest (X, Z) (may lie outside the grid). Not for an unrolled
  /// hull, whose cells share X and Z across the sides (see locate()).
  grid::Cell cell_at(double x, double z) const;
  /// The plane (1 or 2) whose stand-off is nearest the point's distance from the surface at
  /// `cell`, or 0 when neither is within `tolerance_m`.
  int plane_at(grid::Cell cell, double y, double tolerance_m) const;

  /// A grid position and plane a ship-frame point is the pose of.
  struct Located {
    grid::Cell cell{-1, -1};
    int plane = 0;  ///< 0: the point is no cell's pose within the tolerance
  };
  /// The cell and plane whose pose lies within `tolerance_m` of (x, y, z): cell_at() and
  /// plane_at() on one side; on an unrolled hull the nearest pose over every cell and plane.
  Located locate(double x, double y, double z, double tolerance_m) const;

  bool unrolled() const { return spec_.side == HullSide::kBoth; }

  const ShipFrameSpec& spec() const { return spec_; }

 private:
  ShipFrameSpec spec_;
  double sign_;  // +1 port, −1 starboard
};

/// The ship frame a trace's mission was flown in: its grid, footprints, θ (`camera.theta_deg`,
/// else `parameters.theta`, else 90°) and, when the trace has one, its `ship_frame` geometry.
/// `source` names the file in errors.
ShipFrameSpec ship_frame_spec(const nlohmann::json& trace, const std::string& source = "trace");

}  // namespace hullinspect::io
