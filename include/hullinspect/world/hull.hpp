#pragma once
// Hull masks: which cells of the a × b grid are part of the hull, and their loaders.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/world/hull_geometry.hpp"

namespace hullinspect::world {

/// Largest accepted grid side; larger masks are rejected as absurd.
inline constexpr int kMaxGridSide = 4096;

class HullMask {
 public:
  /// Validates the mask: non-empty, sides within [1, kMaxGridSide], hull cells 4-connected.
  /// Throws InputError naming `source` on failure.
  HullMask(grid::Grid<std::uint8_t> is_hull, std::string source);

  int width() const { return mask_.width(); }
  int height() const { return mask_.height(); }
  bool is_hull(int x, int y) const { return mask_(x, y) != 0; }
  bool is_hull(grid::Cell c) const { return mask_[c] != 0; }
  bool is_hull(int index) const { return mask_[index] != 0; }
  /// 1 for hull cells, 0 otherwise.
  const grid::Grid<std::uint8_t>& mask() const { return mask_; }
  int cell_count() const { return cell_count_; }
  /// Flat indices of the hull cells in increasing (y, x) order.
  const std::vector<int>& cells() const { return cells_; }
  /// Where the mask came from (a path, or "builtin:default").
  const std::string& source() const { return source_; }
  /// The nearest hull cell to c by Manhattan distance; ties: lowest y, then lowest x.
  grid::Cell snap(grid::Cell c) const;
  /// The ship-frame geometry of a hull imported from a mesh; nullptr for a plain mask.
  const HullGeometry* geometry() const { return geometry_.get(); }
  /// Attaches geometry (validated against this mask; throws InputError naming `source`).
  void attach_geometry(HullGeometry geometry);

 private:
  grid::Grid<std::uint8_t> mask_;
  std::vector<int> cells_;
  int cell_count_ = 0;
  std::string source_;
  std::shared_ptr<const HullGeometry> geometry_;  // shared: masks are copied freely
};

/// The built-in 230 × 30 ship side profile (data/hulls/default.txt, compiled in).
const HullMask& default_hull();

/// Loads a hull by file name: "default" (or "builtin:default"), a text mask (see docs/formats.md),
/// an ASCII (P2) / binary (P5) PGM image, or a hull JSON with geometry (`*.json`, see
/// hull_geometry.hpp). Throws InputError naming the file and line. Meshes and named mesh hulls
/// ("dtc") are loaded by mesh::load_any_hull, which falls back to this.
HullMask load_hull(const std::filesystem::path& path);
/// Whether `spec` names a hull rather than a file ("default", "builtin:default" or a named mesh
/// hull such as "dtc"): load_hull takes it as it is, never relative to a directory.
bool is_hull_name(std::string_view spec);

/// Parses a text mask: rows top (y = b-1) first, 'X' or '#' hull, '.' non-hull, lines starting
/// with ';' are comments. `source` names the text in errors.
HullMask parse_text_mask(std::string_view text, const std::string& source);

/// Parses a P2 or P5 PGM; pixels with value > maxval/2 are hull; the first image row is y = b-1.
HullMask parse_pgm_mask(std::string_view bytes, const std::string& source);

/// Writes the mask in the text format (round-trips through parse_text_mask).
std::string to_text_mask(const HullMask& hull);

}  // namespace hullinspect::world
