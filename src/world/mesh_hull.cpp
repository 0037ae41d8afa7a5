// Mesh hull files and the named mesh hulls.
#include "hullinspect/world/mesh_hull.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/files/atomic_file.hpp"

namespace hullinspect::world {

namespace {

/// Debian's openfoam-examples installs the DTC here (GPL-3+: read in place, never copied).
constexpr const char* kDtcPath =
    "/usr/share/doc/openfoam-examples/examples/resources/geometry/DTC-scaled.stl.gz";
constexpr double kDtcScale = 59.4;  // the file is the 1:59.4 model

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// "stl", "obj" or "ply" for mesh names (ignoring a trailing .gz), else "".
std::string mesh_format(const std::filesystem::path& path) {
  std::string name = lower(path.filename().string());
  if (name.ends_with(".gz")) name.resize(name.size() - 3);
  for (const char* format : {"stl", "obj", "ply"}) {
    if (name.ends_with(std::string(".") + format)) return format;
  }
  return "";
}

}  // namespace

bool is_mesh_path(const std::filesystem::path& path) {
  return !mesh_format(path).empty();
}

namespace {

MeshImport import_named(const std::filesystem::path& path, const MeshImportOptions& options,
                        const std::string& source) {
  options.validate();
  const std::string bytes = io::read_file(path);
  if (bytes.size() > kMaxMeshBytes) {
    throw InputError(source, 0, fmt::format("mesh is larger than {} MiB", kMaxMeshBytes >> 20));
  }
  const std::vector<MeshTriangle> triangles = read_mesh(bytes, mesh_format(path), source);
  return project_mesh(triangles, options, source);
}

}  // namespace

MeshImport import_mesh_file(const std::filesystem::path& path, const MeshImportOptions& options) {
  return import_named(path, options, path.string());
}

bool is_named_mesh_hull(std::string_view name) {
  return name == "dtc";
}

std::filesystem::path dtc_mesh_path() {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(kDtcPath, ec)) {
    throw InputError("dtc", 0,
                     fmt::format("the DTC mesh is not installed (expected {}; install the Debian "
                                 "package openfoam-examples)",
                                 kDtcPath));
  }
  return kDtcPath;
}

MeshImportOptions dtc_options() {
  MeshImportOptions o;
  o.side = HullSide::starboard;
  o.cell_size = 0.5;
  o.scale = kDtcScale;
  o.axes = AxisMap::parse("x,y,z");  // the file is already x stern→bow, y to port, z up
  return o;
}

MeshImport import_named_mesh_hull(std::string_view name, const MeshImportOptions& options) {
  if (!is_named_mesh_hull(name)) {
    throw InputError(std::string(name), 0, "not a named mesh hull (expected dtc)");
  }
  return import_named(dtc_mesh_path(), options, std::string(name));
}

HullMask load_any_hull(const std::filesystem::path& path, const MeshImportOptions& mesh_options,
                       std::vector<std::string>* warnings) {
  const std::string name = path.string();
  if (!is_named_mesh_hull(name) && !is_mesh_path(path)) return load_hull(path);
  // A named hull brings its own options and is recorded by its name, so runs can be repeated.
  MeshImport imported = is_named_mesh_hull(name)
                            ? import_named(dtc_mesh_path(), dtc_options(), name)
                            : import_mesh_file(path, mesh_options);
  if (warnings) {
    warnings->insert(warnings->end(), imported.warnings.begin(), imported.warnings.end());
  }
  return std::move(imported.hull);
}

}  // namespace hullinspect::world
