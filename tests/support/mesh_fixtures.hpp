#pragma once
// Mesh hulls for tests: Wigley hulls written by tools/make_wigley_hull.py, and the installed DTC.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "hullinspect/world/mesh_hull.hpp"

namespace hullinspect::testing {

struct WigleyHull {
  double length = 100, beam = 10, draft = 8;
  int nx = 200, nz = 40;
  bool binary = false;
};

/// Writes the hull with tools/make_wigley_hull.py into a per-process temporary directory (once per
/// distinct hull) and returns the STL's path. Fails the test if the tool fails.
std::filesystem::path wigley_stl(const WigleyHull& hull);

/// Half-breadth y = (B/2)(1 − (2x/L)²)(1 − (z/T)²) of the hull at (x, z), z in [−T, 0].
double wigley_half_breadth(const WigleyHull& hull, double x, double z);

/// A closed box [x0,x1] × [y0,y1] × [z0,z1] of 12 facets wound counter-clockwise seen from outside.
std::vector<world::MeshTriangle> box_mesh(double x0, double x1, double y0, double y1, double z0,
                                          double z1);

/// The installed DTC mesh, or nullopt (with the reason in `why`) when openfoam-examples is absent.
std::optional<std::filesystem::path> installed_dtc(std::string& why);

}  // namespace hullinspect::testing
