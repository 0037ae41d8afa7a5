#pragma once
// Mesh import options, shared by `hull import` and every command that takes --hull (a mesh file
// given to --hull is imported with them; a named mesh hull such as dtc starts from its own
// options and takes the ones given).

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

#include "hullinspect/world/mesh_hull.hpp"

namespace hullinspect::cli {

struct MeshArgs {
  std::optional<std::string> side;
  std::optional<double> cell_size;
  std::optional<double> scale;
  std::optional<std::string> axes;
  std::optional<double> waterline;
  std::optional<double> min_coverage;
  bool keep_largest = false;
  std::vector<std::string> include;  ///< transom (bottom is refused)
  std::optional<double> max_area_error;
};

void add_mesh_options(CLI::App& cmd, MeshArgs& args);
/// `base` with the options given; throws ParameterError naming the option.
world::MeshImportOptions mesh_import_options(const MeshArgs& args,
                                             world::MeshImportOptions base = {});
/// Imports a mesh file or a named mesh hull with the options given; prints warnings to stderr.
world::MeshImport import_mesh_argument(const std::string& mesh, const MeshArgs& args);
/// Loads --hull: a mesh or named mesh hull (import_mesh_argument), else anything load_hull reads.
world::HullMask load_hull_argument(const std::string& hull, const MeshArgs& args);

}  // namespace hullinspect::cli
