// Fuzz target: hullinspect's own side of the mesh import, in-process (docs/reliability.md,
// "Fuzzing"): the triangles the mesh reader's child process sends back, projected with a depth
// buffer into a hull (world::project_mesh). fuzz_mesh reaches the same code through Assimp in a
// child process per input (a fork each time: slow); this target skips Assimp, so it runs at the
// speed of the projection and a long campaign can reach it as often as the parsers.
//
// Input: byte 0 picks the options (bit 0 port side, bit 1 keep_largest, bit 2 a waterline at
// ship-frame Z 0, bits 3–4 min_coverage), byte 1 the axis map (one of the 48 signed
// permutations), then 36 bytes per triangle: nine floats, as the child's reply carries them.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/mesh_hull.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hullinspect::world;
  if (size < 2) return 0;
  constexpr std::size_t kTriangleBytes = 9 * sizeof(float);
  std::vector<MeshTriangle> triangles((size - 2) / kTriangleBytes);
  double extent = 0;
  const std::uint8_t* p = data + 2;
  for (MeshTriangle& t : triangles) {
    float xyz[9];
    std::memcpy(xyz, p, sizeof xyz);
    p += sizeof xyz;
    for (std::size_t k = 0; k < 3; ++k) {
      for (std::size_t c = 0; c < 3; ++c) {
        t.v[k][c] = static_cast<double>(xyz[3 * k + c]);
        if (std::isfinite(t.v[k][c])) extent = std::max(extent, std::abs(t.v[k][c]));
      }
    }
  }
  MeshImportOptions options;
  if (data[0] & 1) options.side = HullSide::port;
  options.keep_largest = (data[0] & 2) != 0;
  if (data[0] & 4) options.waterline = 0.0;
  static constexpr double kCoverage[] = {0.5, 0.25, 1.0, 0.01};
  options.min_coverage = kCoverage[(data[0] >> 3) & 3];
  static constexpr std::array<std::array<int, 3>, 6> kPermutations = {
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  const int axes = data[1] % 48;
  options.axes.axis = kPermutations[static_cast<std::size_t>(axes / 8)];
  for (std::size_t i = 0; i < 3; ++i) options.axes.sign[i] = (axes >> i) & 1 ? -1 : 1;
  // The cell size follows the extent, so every grid stays at most ~16 cells a side: the
  // rasteriser's work grows with the cells (49 samples each) while its branches do not, and a
  // grid too large is a refusal the parsers' own targets already cover.
  if (extent > 1e30) return 0;
  options.cell_size = std::max(extent / 8, 1e-6);
  try {
    (void)project_mesh(triangles, options, "fuzz.mesh");
  } catch (const hullinspect::Error&) {
  }
  return 0;
}
