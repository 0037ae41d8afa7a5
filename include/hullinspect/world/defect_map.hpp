#pragma once
// Corrosion maps from a list of defects in ship coordinates (docs/hulls.md "Defects from a
// survey"): what a crew has from the last dry-dock survey — a position along the hull (metres from
// the ship-frame origin, or a frame number), a height, a side and a size — rasterised onto whatever
// grid the hull has.
//
// A hull cell is corroded when the centre of its surface lies in a defect's rectangle on the side
// the hull shows; a defect smaller than a cell that holds no cell centre marks the cell holding the
// defect's own centre, so that no reported defect is lost to the raster.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/hull_geometry.hpp"
#include "hullinspect/world/user_maps.hpp"

namespace hullinspect::world {

/// One defect: a rectangle on one side of the hull, centred at (x_m, z_m) in the ship frame,
/// w_m long (along x) and h_m high (along z).
struct Defect {
  double x_m = 0;
  double z_m = 0;
  HullSide side = HullSide::starboard;
  double w_m = 0;
  double h_m = 0;
  int line = 0;       ///< its line in a CSV file (0 for JSON)
  std::string where;  ///< "defects[3]" in a JSON file: for error messages
};

/// How frame numbers become metres: x = frame_zero_m + frame × frame_spacing_m.
struct FrameSpacing {
  std::optional<double> frame_spacing_m;  ///< needed only by files that give frames
  double frame_zero_m = 0;
};

/// Reads a defects file: CSV (a header naming the columns `x_m` or `frame`, `z_m`, `side`, `w_m`,
/// `h_m` in any order; `#` comment lines) or, for `*.json`, `{"defects": [{…}, …]}` with the same
/// keys. Throws InputError naming the file and the line (CSV) or the defect (JSON).
std::vector<Defect> read_defects(const std::filesystem::path& path, const FrameSpacing& frames);

/// Rasterises `defects` onto `hull`'s grid, placed in the ship frame by its geometry (a mask
/// without a mesh: 0.5 m cells, origin at its bottom-left corner, seen from starboard). Throws
/// InputError naming `source` and the defect when it lies on the side the hull does not show or
/// marks no hull cell.
CorrosionMap rasterise_defects(const std::vector<Defect>& defects, const std::string& source,
                               const HullMask& hull);

/// read_defects then rasterise_defects.
CorrosionMap load_defect_map(const std::filesystem::path& path, const HullMask& hull,
                             const FrameSpacing& frames);

}  // namespace hullinspect::world
