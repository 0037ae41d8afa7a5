#include "support/mesh_fixtures.hpp"
#include "source_dir.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/mesh_hull.hpp"

namespace hullinspect::testing {

std::vector<world::MeshTriangle> box_mesh(double x0, double x1, double y0, double y1, double z0,
                                          double z1) {
  using Vec = std::array<double, 3>;
  std::vector<world::MeshTriangle> t;
  const auto quad = [&](Vec a, Vec b, Vec c, Vec d) {
    t.push_back(world::MeshTriangle{{a, b, c}});
    t.push_back(world::MeshTriangle{{a, c, d}});
  };
  quad({x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1});  // starboard (−y)
  quad({x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0});  // port (+y)
  quad({x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1});  // top
  quad({x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}, {x1, y0, z0});  // bottom
  quad({x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0});  // stern
  quad({x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1});  // bow
  return t;
}

std::filesystem::path wigley_stl(const WigleyHull& h) {
  const auto dir =
      std::filesystem::temp_directory_path() / fmt::format("hullinspect_wigley_{}", ::getpid());
  std::filesystem::create_directories(dir);
  const auto path = dir / fmt::format("wigley_{}_{}_{}_{}_{}{}.stl", h.length, h.beam, h.draft,
                                      h.nx, h.nz, h.binary ? "_bin" : "");
  if (!std::filesystem::exists(path)) {
    const std::string command = fmt::format(
        "/usr/bin/python3 {}/tools/make_wigley_hull.py '{}' --length {} --beam {} --draft {} "
        "--nx {} --nz {}{} > /dev/null",
        HULLINSPECT_SOURCE_DIR, path.string(), h.length, h.beam, h.draft, h.nx, h.nz,
        h.binary ? " --binary" : "");
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
  }
  return path;
}

double wigley_half_breadth(const WigleyHull& h, double x, double z) {
  const double u = 2 * x / h.length, v = z / h.draft;
  return 0.5 * h.beam * (1 - u * u) * (1 - v * v);
}

std::optional<std::filesystem::path> installed_dtc(std::string& why) {
  try {
    return world::dtc_mesh_path();
  } catch (const Error& e) {
    why = e.what();
    return std::nullopt;
  }
}

}  // namespace hullinspect::testing
