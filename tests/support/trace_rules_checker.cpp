#include "support/trace_rules_checker.hpp"

#include "hullinspect/core/errors.hpp"
#include "hullinspect/io/trace_reader.hpp"
#include "hullinspect/io/trace_rules.hpp"
#include "hullinspect/io/traced_mission.hpp"

namespace hullinspect::testing {

nlohmann::json recorded_trace(const planners::MissionSpec& spec, const world::HullMask& hull) {
  return io::run_traced_mission(spec, hull).trace;
}

::testing::AssertionResult trace_keeps_the_rules(const nlohmann::json& trace) {
  try {
    io::validate_trace(trace, "trace");
    io::check_trace_safety(trace, "trace");
  } catch (const InputError& e) {
    return ::testing::AssertionFailure() << e.what();
  }
  return ::testing::AssertionSuccess();
}

}  // namespace hullinspect::testing
