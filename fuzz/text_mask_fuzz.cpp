// Fuzz target: the text hull mask parser (docs/formats.md).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/hull.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto hull = hullinspect::world::parse_text_mask(text, "fuzz.txt");
    // A parsed mask must round-trip through the writer.
    const auto again =
        hullinspect::world::parse_text_mask(hullinspect::world::to_text_mask(hull), "again");
    if (again.cell_count() != hull.cell_count()) __builtin_trap();
  } catch (const hullinspect::Error&) {
  }
  return 0;
}
