// hullinspect hull import: a mesh (STL, OBJ, PLY, optionally .gz) or a named mesh hull → a hull
// JSON (mask + geometry, docs/formats.md) that every --hull accepts.

#include <fmt/format.h>

#include <cmath>
#include <iostream>

#include "commands.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/files/output_set.hpp"
#include "hullinspect/world/mesh_hull.hpp"
#include "mission_options.hpp"

namespace hullinspect::cli {

namespace {

struct HullImportArgs {
  std::string mesh;
  std::string out;
  MissionArgs options;  // only its mesh options are registered
};

std::string output_path(const std::string& out) {
  return out.ends_with(".json") ? out : out + ".json";
}

int import(const HullImportArgs& args) {
  if (args.out.empty()) throw ParameterError("out", "expects a file name");
  const std::string out = output_path(args.out);
  io::OutputSet outputs;
  outputs.add_output(out, "out");
  outputs.check();
  const world::MeshImport imported = import_mesh_argument(args.mesh, args.options.mesh);
  const world::HullMask& hull = imported.hull;
  const world::HullGeometry& g = *hull.geometry();
  outputs.write(out, world::to_hull_json(hull));
  if (g.unrolled()) {
    std::cout << fmt::format("{}: {} facets, unrolled (port, bow, starboard{})\n", args.mesh,
                             imported.facets, args.options.mesh.include.empty() ? "" : ", transom");
  } else {
    std::cout << fmt::format("{}: {} facets, {} facing {}\n", args.mesh, imported.facets,
                             imported.facing_facets, world::to_string(g.side));
  }
  std::cout << fmt::format("  grid {} × {} cells of {} m, {} hull cells ({:.1f} m²)\n",
                           hull.width(), hull.height(), g.cell_size, hull.cell_count(),
                           hull.cell_count() * g.cell_size * g.cell_size);
  float max_depth = 0;
  for (int i : hull.cells()) max_depth = std::max(max_depth, g.depth[i]);
  // Rounded before printing so that a tiny negative value does not print as "-0.000".
  const auto metres = [](double v) { return std::round(v * 1000) / 1000 + 0.0; };
  if (g.unrolled()) {
    std::cout << fmt::format(
        "  surface {:.1f} m²; cell-area error worst {:.1f} % at cell ({}, {}), mean {:.1f} %\n",
        imported.surface_area, 100 * imported.worst_area_error, imported.worst_area_cell.x,
        imported.worst_area_cell.y, 100 * imported.mean_area_error);
    std::cout << fmt::format(
        "  columns from {:.3f} m (port) to {:.3f} m (starboard) around the "
        "bow; Z0 = {:.3f} m\n",
        metres(g.x0), metres(g.x0 + hull.width() * g.cell_size), metres(g.z0));
    // The grid closes on itself: a flight at stand-off links its ends (docs/model.md "Neighbour
    // flights").
    if (g.seam) {
      std::cout << "  seam: columns 0 and " << hull.width() - 1
                << " meet at the transom, linked by a flight at stand-off\n";
    }
  } else {
    std::cout << fmt::format(
        "  origin X0 = {:.3f} m, Z0 = {:.3f} m; side plane Y = {:.3f} m; depth up to {:.3f} m\n",
        metres(g.x0), metres(g.z0), metres(g.side_plane_y), metres(max_depth));
  }
  std::cout << fmt::format("  wrote {}\n", out);
  check_stdout();  // a command whose printed result is lost leaves no file
  outputs.commit();
  return 0;
}

}  // namespace

void add_hull_command(CLI::App& app, CommandAction& action) {
  CLI::App* hull = app.add_subcommand("hull", "Hull tools: import a mesh as a hull");
  hull->require_subcommand(1);
  auto args = std::make_shared<HullImportArgs>();
  CLI::App* cmd = hull->add_subcommand(
      "import", "Project a mesh (STL, OBJ, PLY, optionally .gz) onto a hull mask with geometry");
  cmd->footer(
      "MESH may also be a named mesh hull: dtc (the installed Duisburg Test Case, full scale).\n"
      "Example: hullinspect hull import wigley.stl --out wigley --cell-size 0.5");
  cmd->add_option("MESH", args->mesh, "Mesh file or named mesh hull")->required();
  cmd->add_option("--out,-o", args->out, "Write the hull to NAME.json (mask + geometry)")
      ->type_name("NAME")
      ->required();
  add_mesh_options(*cmd, args->options);
  cmd->callback([args, &action] { action = [args] { return import(*args); }; });
}

}  // namespace hullinspect::cli
