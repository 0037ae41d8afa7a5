#pragma once
// Hulls from 3D meshes (docs/model.md "Hulls from meshes"): read STL/OBJ/PLY (optionally gzip-
// compressed) with Assimp, map to the ship frame, project the facets facing one side onto the x–z
// plane with a depth buffer, and keep the cells covered enough as the hull mask plus its geometry.

#include <array>
#include <chrono>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/hull_geometry.hpp"

namespace hullinspect::world {

/// Largest mesh file accepted, after decompression.
inline constexpr std::size_t kMaxMeshBytes = 512u * 1024 * 1024;

struct MeshImportOptions {
  HullSide side = HullSide::starboard;
  double cell_size = 0.5;           ///< metres, ship frame
  double scale = 1;                 ///< applied to the file's coordinates
  AxisMap axes;                     ///< file axes → ship axes
  std::optional<double> waterline;  ///< ship-frame Z (metres); cells below are not hull
  double min_coverage = 0.5;        ///< fraction of a cell's area that makes it hull
  bool keep_largest = false;        ///< keep the largest 4-connected component instead of failing
  /// Unrolled hulls (side both) only: also unroll the transom, closing the grid around the stern
  /// with a seam at the stern's centre line.
  bool include_transom = false;
  /// Refused: a UAV standing off horizontally cannot see the bottom (docs/hulls.md).
  bool include_bottom = false;
  /// Unrolled hulls only: refuse an import whose worst cell-area error is above this fraction.
  std::optional<double> max_area_error;

  /// Throws ParameterError naming the option ("cell-size", "scale", "min-coverage", "waterline",
  /// "include", "max-area-error").
  void validate() const;
};

/// One facet as read from the file (file frame, before axes and scale).
struct MeshTriangle {
  std::array<std::array<double, 3>, 3> v;
  friend bool operator==(const MeshTriangle&, const MeshTriangle&) = default;
};

struct MeshImport {
  HullMask hull;
  std::vector<std::string> warnings;  ///< e.g. components dropped by keep_largest
  int facets = 0;                     ///< facets in the file
  int facing_facets = 0;              ///< facets facing the chosen side
  /// Unrolled hulls only: the surface area of the hull cells (m²) and how far a cell's surface
  /// area departs from cell² × coverage (a fraction; worst and mean over the hull cells).
  double surface_area = 0;
  double worst_area_error = 0;
  double mean_area_error = 0;
  grid::Cell worst_area_cell{-1, -1};
};

/// True for names ending in .stl, .obj, .ply, optionally followed by .gz (any case).
bool is_mesh_path(const std::filesystem::path& path);

/// Wall-time limit of the child process that runs Assimp on `bytes` (decompressed) bytes:
/// 60 s + 1 s per MiB (the 39 MB DTC is read in under a second).
std::chrono::milliseconds mesh_reader_time_limit(std::size_t bytes);

/// Parses mesh bytes with Assimp; gzip data (magic 1f 8b) is inflated in memory first. `hint` is
/// the format's extension ("stl", "obj", "ply"). Throws InputError naming `source`.
/// Assimp runs in a child process (core/isolated_call.hpp): a crash inside it, or a read not done
/// within `time_limit` (0: mesh_reader_time_limit), is an InputError too ("not a readable ply mesh
/// (the mesh reader crashed: signal 11)"). Safe to call from any thread, but call it before
/// starting threads where possible: see the fork caveat in core/isolated_call.hpp.
std::vector<MeshTriangle> read_mesh(std::string_view bytes, std::string_view hint,
                                    const std::string& source,
                                    std::chrono::milliseconds time_limit = {});

namespace detail {
/// read_mesh's child process alone, without the checks before it (tests reach Assimp's known hang
/// through it). `format` is "stl", "obj" or "ply".
std::vector<MeshTriangle> read_mesh_in_child(std::string_view bytes, const std::string& format,
                                             const std::string& source,
                                             std::chrono::milliseconds time_limit);
}  // namespace detail

/// Projects the triangles (SPEC-model §Hulls from meshes) into a hull with geometry. Throws
/// InputError naming `source` when nothing faces the side, the grid is too large, no cell is hull,
/// or (without keep_largest) the hull is not 4-connected.
MeshImport project_mesh(std::span<const MeshTriangle> triangles, const MeshImportOptions& options,
                        const std::string& source);

/// Unrolls a closed mesh (options.side == both) into one grid: columns by arc length along the
/// horizontal section from stern-port over the bow to stern-starboard, rows by height
/// (docs/hulls.md "The whole hull"). project_mesh calls it for side both. Throws InputError naming
/// `source` when a section is open or has several outlines (not one closed body), and when the
/// worst cell-area error is above options.max_area_error.
MeshImport unroll_mesh(std::span<const MeshTriangle> triangles, const MeshImportOptions& options,
                       const std::string& source);

namespace detail {
/// A geometry of width × height cells with the options' provenance, no surface and no coverage.
HullGeometry empty_geometry(const MeshImportOptions& options, const std::string& source, double x0,
                            double z0, int width, int height);
/// The end of every import: checks the hull cells are 4-connected (or keeps the largest part
/// with a warning), attaches the geometry.
MeshImport finish_import(grid::Grid<std::uint8_t> is_hull, HullGeometry geometry,
                         const MeshImportOptions& options, const std::string& source);
}  // namespace detail

/// Reads and projects a mesh file.
MeshImport import_mesh_file(const std::filesystem::path& path, const MeshImportOptions& options);

/// The named mesh hulls: "dtc" (the Duisburg Test Case container ship from Debian's
/// openfoam-examples, full scale ×59.4, starboard, 0.5 m cells).
bool is_named_mesh_hull(std::string_view name);
/// The installed DTC mesh; throws InputError("dtc", …) when the package is not installed.
std::filesystem::path dtc_mesh_path();
MeshImportOptions dtc_options();
/// Imports a named mesh hull with `options` (normally its own, e.g. dtc_options()); the hull's
/// source is the name, so runs record "dtc" rather than a path.
MeshImport import_named_mesh_hull(std::string_view name, const MeshImportOptions& options);

/// Loads any hull: a named mesh hull ("dtc"), a mesh file (imported with `mesh_options`), or
/// anything load_hull accepts. Warnings (keep_largest) are appended to `warnings` when given.
HullMask load_any_hull(const std::filesystem::path& path,
                       const MeshImportOptions& mesh_options = {},
                       std::vector<std::string>* warnings = nullptr);

}  // namespace hullinspect::world
