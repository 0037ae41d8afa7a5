// Fuzz target: the mission trace reader (JSON parsing and validation, docs/trace-format.md).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/files/json_document.hpp"
#include "hullinspect/io/trace_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto trace = hullinspect::io::parse_json_document(text, "fuzz.json", "a JSON trace");
    hullinspect::io::validate_trace(trace, "fuzz.json");
  } catch (const hullinspect::Error&) {
  }
  return 0;
}
