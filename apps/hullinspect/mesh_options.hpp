#pragma once
// Mesh import options, shared by `hull import` and every command that takes --hull (a mesh file
// given to --hull is imported with them).

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "hullinspect/world/mesh_hull.hpp"

namespace hullinspect::cli {

struct MeshArgs {
  std::string side = "starboard";
  double cell_size = 0.5;
  double scale = 1;
  std::string axes = "x,y,z";
  std::optional<double> waterline;
  double min_coverage = 0.5;
  bool keep_largest = false;
};

void add_mesh_options(CLI::App& cmd, MeshArgs& args);
/// Throws ParameterError naming the option.
world::MeshImportOptions mesh_import_options(const MeshArgs& args);
/// Loads --hull (a mask, a hull JSON, a mesh imported with `args`, or "dtc"); prints import
/// warnings (--keep-largest) to stderr.
world::HullMask load_hull_argument(const std::string& hull, const MeshArgs& args);

}  // namespace hullinspect::cli
