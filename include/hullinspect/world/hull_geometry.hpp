#pragma once
// The 3D geometry behind a hull mask imported from a mesh (docs/model.md "Hulls from meshes"):
// where the grid sits in the ship frame and, per cell, how far the surface stands out from the side
// plane and which way it faces. Masks without a mesh have no geometry (depth 0, flat side).

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "hullinspect/grid/grid.hpp"

namespace hullinspect::world {

class HullMask;

/// The side of the ship being inspected. Starboard is seen from −y looking toward +y (y is to
/// port). `both` is the unrolled hull (docs/hulls.md "The whole hull"): port, bow and starboard in
/// one grid whose columns follow the waterline-direction section by arc length.
enum class HullSide { starboard, port, both };

std::string_view to_string(HullSide side);
/// Parses "starboard", "port" or "both"; throws ParameterError("side", …) otherwise.
HullSide parse_hull_side(std::string_view text);

/// How a mesh file's axes map to the ship frame (x stern→bow, y to port, z up): ship axis i is
/// sign[i] × file axis axis[i]. Written like "x,-z,y" (ship x = file x, ship y = −file z, ship z =
/// file y).
struct AxisMap {
  std::array<int, 3> axis{0, 1, 2};
  std::array<int, 3> sign{1, 1, 1};

  /// Throws ParameterError("axes", …) unless `text` is a signed permutation of x, y, z.
  static AxisMap parse(std::string_view text);
  std::string to_string() const;
  /// +1 for a rotation, −1 for a reflection (which reverses the facets' winding).
  int determinant() const;
  friend bool operator==(const AxisMap&, const AxisMap&) = default;
};

/// A unit vector in the ship frame.
struct Normal {
  float x = 0, y = 0, z = 0;
  friend bool operator==(const Normal&, const Normal&) = default;
};

/// A point in the ship frame, metres.
struct Point3 {
  float x = 0, y = 0, z = 0;
  friend bool operator==(const Point3&, const Point3&) = default;
};

/// Ship-frame geometry of a hull grid (docs/model.md): grid position (x, y) is centred at
/// X = x0 + (x + ½)·cell_size, Z = z0 + (y + ½)·cell_size; the hull surface there is at
/// Y = side_plane_y − depth(x, y) seen from starboard, side_plane_y + depth(x, y) from port.
struct HullGeometry {
  double cell_size = 0.5;   ///< metres
  double x0 = 0;            ///< ship-frame X of the grid's stern edge (column 0's left side)
  double z0 = 0;            ///< ship-frame Z of the grid's bottom edge (row 0's lower side)
  double side_plane_y = 0;  ///< Ys: the plane y = Ys through the innermost surface point
  HullSide side = HullSide::starboard;
  AxisMap axes;                     ///< how the mesh's axes were mapped to the ship frame
  double scale = 1;                 ///< uniform scale applied to the mesh
  std::optional<double> waterline;  ///< ship-frame Z below which cells are not hull, if given
  double min_coverage = 0.5;        ///< the fraction of a cell's area that made it hull
  std::string mesh;                 ///< the mesh it was imported from (provenance only)

  /// Metres from the side plane out to the surface (≥ 0, toward the viewer); 0 where no surface.
  grid::Grid<float> depth;
  /// Outward unit normal of the surface at the cell's centre; (0, ∓1, 0) where no surface.
  grid::Grid<Normal> normal;
  /// Fraction of the cell's area covered by projected surface, in [0, 1].
  grid::Grid<float> coverage;
  /// Unrolled hulls only (side == both; empty otherwise): the ship-frame surface point at each
  /// cell's centre. There x0 is the arc length of column 0's left edge measured from the bow
  /// (negative: port is left of the bow, starboard right), depth is 0 (the grid lies on the
  /// surface) and side_plane_y is the centre plane the columns are measured from.
  grid::Grid<Point3> surface;
  /// Unrolled hulls only: the grid closes on itself around the stern (the transom unrolled), so
  /// every row's first and last columns are neighbours across the seam, linked by a flight at
  /// stand-off (docs/hulls.md "Neighbours"). The hull file's optional `seam` (absent: false).
  bool seam = false;

  bool unrolled() const { return side == HullSide::both; }

  int width() const { return depth.width(); }
  int height() const { return depth.height(); }
  /// Ship-frame X (unrolled: arc length from the bow), Z of the centre of grid position (x, y).
  double centre_x(int x) const { return x0 + (x + 0.5) * cell_size; }
  double centre_z(int y) const { return z0 + (y + 0.5) * cell_size; }
  /// +1 when looking from port (outward is +y), −1 from starboard; on an unrolled hull the side of
  /// the column (port left of the bow).
  double outward_sign() const { return side == HullSide::port ? 1.0 : -1.0; }
  /// Ship-frame Y of the surface at (x, y).
  double surface_y(int x, int y) const {
    return unrolled() ? surface(x, y).y : side_plane_y + outward_sign() * depth(x, y);
  }
  /// Ship-frame Y of a UAV `standoff` metres off the surface at (x, y) (docs/model.md §Frames).
  double uav_y(int x, int y, double standoff) const {
    return side_plane_y + outward_sign() * (standoff + depth(x, y));
  }
};

/// Checks the geometry against its mask (same size, finite values, unit normals on hull cells).
/// Throws InputError naming `source` and the field.
void validate(const HullGeometry& geometry, const HullMask& mask, const std::string& source);

/// A hull file: the mask and its geometry in one JSON document (docs/formats.md "Hull geometry").
/// Throws InputError "FILE: field: problem" on any error.
HullMask parse_hull_json(std::string_view text, const std::string& source);
/// Serialises a mask with geometry (round-trips through parse_hull_json). Requires a geometry.
std::string to_hull_json(const HullMask& hull);

}  // namespace hullinspect::world
