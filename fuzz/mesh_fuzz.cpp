// Fuzz target: the mesh import path (docs/hulls.md): bytes → Assimp (STL, OBJ, PLY; gzip) →
// depth-buffered projection. The first byte picks the format hint (0 stl, 1 obj, 2 ply); the cell
// size follows the mesh's extent so every grid stays small. Assimp runs in read_mesh's child
// process, as in the CLI: its crashes, leaks and hangs on corrupt files are errors (InputError),
// not findings; what is fuzzed is hullinspect's side (checks, the child's protocol, projection).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/mesh_hull.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hullinspect::world;
  if (size < 1) return 0;
  static constexpr std::string_view kHints[] = {"stl", "obj", "ply"};
  const std::string_view hint = kHints[data[0] % 3];
  const std::string_view bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    // Well under libFuzzer's -timeout (20 s): a child that hangs in Assimp is an error here.
    const auto triangles = read_mesh(bytes, hint, "fuzz.mesh", std::chrono::seconds(3));
    double extent = 0;
    for (const auto& t : triangles) {
      for (const auto& v : t.v) {
        for (double c : v) extent = std::max(extent, std::abs(c));
      }
    }
    if (!std::isfinite(extent) || extent > 1e30) return 0;
    MeshImportOptions options;
    options.cell_size = std::max(extent / 32, 1e-6);
    options.keep_largest = (data[0] / 3) % 2 == 1;
    if ((data[0] / 6) % 2 == 1) options.side = HullSide::port;
    (void)project_mesh(triangles, options, "fuzz.mesh");
  } catch (const hullinspect::Error&) {
  }
  return 0;
}
