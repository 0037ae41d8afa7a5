// Fuzz target: the hull JSON reader (mask + geometry, docs/formats.md "Hull JSON").

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/hull_geometry.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const auto hull = hullinspect::world::parse_hull_json(bytes, "fuzz.json");
    (void)hullinspect::world::to_hull_json(hull);
  } catch (const hullinspect::Error&) {
  }
  return 0;
}
