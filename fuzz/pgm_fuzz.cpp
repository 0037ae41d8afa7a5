// Fuzz target: the PGM (P2/P5) hull mask parser (docs/formats.md).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/hull.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    (void)hullinspect::world::parse_pgm_mask(bytes, "fuzz.pgm");
  } catch (const hullinspect::Error&) {
  }
  return 0;
}
