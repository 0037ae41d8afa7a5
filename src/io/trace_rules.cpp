#include "hullinspect/io/trace_rules.hpp"

#include "trace_checker.hpp"
#include "trace_motion.hpp"

namespace hullinspect::io {

void check_trace_safety(const nlohmann::json& trace, const std::string& source) {
  const detail::TraceChecker check(source);
  const auto mission = detail::trace_mission(
      check, trace, trace["version"].get<int>(), trace["grid"]["width"].get<int>(),
      trace["grid"]["height"].get<int>(), trace["plane_change_steps"].get<int>());
  const auto counts = detail::check_motion(check, trace["frames"], mission);
  // The first breach of each rule reads "frames[t].u: <what>"; the field is the part before ": ".
  for (const std::string* breach :
       {&counts.first_crash, &counts.first_low_landing, &counts.first_conflict}) {
    if (breach->empty()) continue;
    const auto colon = breach->find(": ");
    check.fail(breach->substr(0, colon), breach->substr(colon + 2));
  }
}

}  // namespace hullinspect::io
