#include "mesh_options.hpp"

#include <iostream>

namespace hullinspect::cli {

void add_mesh_options(CLI::App& cmd, MeshArgs& a) {
  const char* group = "Mesh hulls";
  cmd.add_option("--side", a.side, "Mesh hulls: side inspected, port or starboard")
      ->group(group)
      ->capture_default_str();
  cmd.add_option("--cell-size", a.cell_size, "Mesh hulls: cell side in metres")
      ->group(group)
      ->capture_default_str();
  cmd.add_option("--scale", a.scale, "Mesh hulls: uniform scale applied to the file's coordinates")
      ->group(group)
      ->capture_default_str();
  cmd.add_option("--axes", a.axes,
                 "Mesh hulls: ship x,y,z (stern→bow, to port, up) as signed file axes, e.g. x,-z,y")
      ->group(group)
      ->capture_default_str();
  cmd.add_option(
         "--waterline", a.waterline,
         "Mesh hulls: ship-frame Z in metres below which cells are not hull (default: none)")
      ->group(group)
      ->type_name("Z");
  cmd.add_option("--min-coverage", a.min_coverage,
                 "Mesh hulls: fraction of a cell that must be surface to be hull, in (0, 1]")
      ->group(group)
      ->capture_default_str();
  cmd.add_flag("--keep-largest", a.keep_largest,
               "Mesh hulls: keep the largest 4-connected part of the projection (else an error)")
      ->group(group);
}

world::MeshImportOptions mesh_import_options(const MeshArgs& a) {
  world::MeshImportOptions o;
  o.side = world::parse_hull_side(a.side);
  o.cell_size = a.cell_size;
  o.scale = a.scale;
  o.axes = world::AxisMap::parse(a.axes);
  o.waterline = a.waterline;
  o.min_coverage = a.min_coverage;
  o.keep_largest = a.keep_largest;
  o.validate();
  return o;
}

world::HullMask load_hull_argument(const std::string& hull, const MeshArgs& args) {
  std::vector<std::string> warnings;
  world::HullMask mask = world::load_any_hull(hull, mesh_import_options(args), &warnings);
  for (const std::string& w : warnings) std::cerr << "hullinspect: warning: " << w << "\n";
  return mask;
}

}  // namespace hullinspect::cli
