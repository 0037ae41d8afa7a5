#include "mesh_options.hpp"

#include <fmt/format.h>

#include <iostream>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::cli {

void add_mesh_options(CLI::App& cmd, MeshArgs& a) {
  const char* group = "Mesh hulls (see docs/hulls.md)";
  // The defaults shown are those of MeshImportOptions itself (declared once, in mesh_hull.hpp):
  // the options are optional here so that a named mesh hull can start from its own.
  const world::MeshImportOptions d;
  const auto number = [](double v) { return fmt::format("{}", v); };
  cmd.add_option("--side,--sides", a.side,
                 "Side inspected: port, starboard, or both (the whole hull unrolled into one grid)")
      ->default_str(std::string(world::to_string(d.side)))
      ->group(group);
  cmd.add_option("--cell-size", a.cell_size, "Cell side in metres")
      ->default_str(number(d.cell_size))
      ->group(group);
  cmd.add_option("--scale", a.scale, "Uniform scale applied to the file's coordinates")
      ->default_str(number(d.scale))
      ->group(group);
  cmd.add_option("--axes", a.axes,
                 "Ship x,y,z (stern→bow, to port, up) as signed file axes, e.g. x,-z,y")
      ->default_str(d.axes.to_string())
      ->group(group);
  auto* waterline = cmd.add_option("--waterline", a.waterline,
                                   "Ship-frame Z in metres below which cells are not hull");
  waterline->group(group)->type_name("Z");
  if (d.waterline) {
    waterline->default_str(number(*d.waterline));
  } else {
    waterline->description(waterline->get_description() + " (default: none, a hull in dry dock)");
  }
  cmd.add_option("--min-coverage", a.min_coverage,
                 "Fraction of a cell that must be surface for it to be hull, in (0, 1]")
      ->default_str(number(d.min_coverage))
      ->group(group);
  cmd.add_flag("--keep-largest", a.keep_largest,
               "Keep the largest 4-connected part of the projection (else an error)")
      ->group(group);
  cmd.add_option("--include", a.include,
                 "With --sides both: also unroll the transom (closing the grid around the stern)")
      ->type_name("transom")
      ->delimiter(',')
      ->group(group);
  cmd.add_option("--max-area-error", a.max_area_error,
                 "With --sides both: refuse an import whose worst cell-area error is above this "
                 "fraction (0.1 is 10 %; default: no limit)")
      ->group(group);
}

world::MeshImportOptions mesh_import_options(const MeshArgs& a, world::MeshImportOptions o) {
  if (a.side) o.side = world::parse_hull_side(*a.side);
  if (a.cell_size) o.cell_size = *a.cell_size;
  if (a.scale) o.scale = *a.scale;
  if (a.axes) o.axes = world::AxisMap::parse(*a.axes);
  if (a.waterline) o.waterline = a.waterline;
  if (a.min_coverage) o.min_coverage = *a.min_coverage;
  if (a.keep_largest) o.keep_largest = true;
  for (const std::string& part : a.include) {
    if (part == "transom") {
      o.include_transom = true;
    } else if (part == "bottom") {
      o.include_bottom = true;
    } else {
      throw ParameterError("include", fmt::format("expected transom, got '{}'", part));
    }
  }
  if (a.max_area_error) o.max_area_error = a.max_area_error;
  o.validate();
  return o;
}

world::MeshImport import_mesh_argument(const std::string& mesh, const MeshArgs& args) {
  world::MeshImport r =
      world::is_named_mesh_hull(mesh)
          ? world::import_named_mesh_hull(mesh, mesh_import_options(args, world::dtc_options()))
          : world::import_mesh_file(mesh, mesh_import_options(args));
  for (const std::string& w : r.warnings) std::cerr << "hullinspect: warning: " << w << "\n";
  return r;
}

world::HullMask load_hull_argument(const std::string& hull, const MeshArgs& args) {
  if (world::is_named_mesh_hull(hull) || world::is_mesh_path(hull)) {
    return std::move(import_mesh_argument(hull, args).hull);
  }
  // Options given with a plain mask are still checked.
  if (mesh_import_options(args).side == world::HullSide::both) {
    throw ParameterError("sides", "both needs a mesh hull: a mask has no 3D surface to unroll");
  }
  return world::load_hull(hull);
}

}  // namespace hullinspect::cli
