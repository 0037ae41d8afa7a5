// Fuzz target: the segment-TSP instance JSON parser (docs/tsp.md).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/io/tsp_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto problem = hullinspect::io::parse_tsp_instance(text, "fuzz.json");
    // What was read must be written back and read again identically.
    const auto again = hullinspect::io::parse_tsp_instance(
        hullinspect::io::tsp_instance_json(problem).dump(), "again.json");
    if (again.segments.size() != problem.segments.size()) __builtin_trap();
  } catch (const hullinspect::Error&) {
  }
  return 0;
}
