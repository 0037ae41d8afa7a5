// The readers of exported waypoint files (csv, QGroundControl .plan, QGC WPL 110, nav_msgs/Path
// YAML) that the round-trip tests use: any input is either read or rejected with an InputError.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/io/export_readers.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  using namespace hullinspect;
  for (auto reader :
       {&io::read_export_csv, &io::read_qgc_plan, &io::read_wpl, &io::read_path_yaml}) {
    try {
      (void)reader(text, "fuzz");
    } catch (const InputError&) {
    }
  }
  return 0;
}
