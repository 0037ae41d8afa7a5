#include "hullinspect/io/preflight_separation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <limits>

#include "hullinspect/io/waypoints.hpp"

namespace hullinspect::io {

nlohmann::json preflight_separation(const nlohmann::json& trace, const ExportPlan& plan,
                                    std::vector<std::string>& warnings) {
  using nlohmann::json;
  const auto& parameters = trace.at("parameters");
  const int d = parameters.is_object() ? parameters.value("separation", 0) : 0;
  const auto& result = trace.at("result");
  const long long conflicts = result.value("separation_conflicts", 0LL);

  // The smallest Chebyshev distance between two UAVs at one step (failed UAVs still occupy their
  // cell, as in the simulator's check); ties keep the first step and pair.
  const auto states = trace_states(trace);
  int best = std::numeric_limits<int>::max();
  int best_t = -1, best_a = -1, best_b = -1;
  const std::size_t frames = states.empty() ? 0 : states.front().size();
  for (std::size_t t = 0; t < frames; ++t) {
    for (std::size_t a = 0; a < states.size(); ++a) {
      for (std::size_t b = a + 1; b < states.size(); ++b) {
        const auto pa = states[a][t].pos;
        const auto pb = states[b][t].pos;
        const int gap = std::max(std::abs(pa.x - pb.x), std::abs(pa.y - pb.y));
        if (gap < best) {
          best = gap;
          best_t = static_cast<int>(t);
          best_a = static_cast<int>(a);
          best_b = static_cast<int>(b);
        }
      }
    }
  }
  json out = {{"d", d}, {"conflicts", conflicts}};
  if (best_t < 0) {
    out["min_cells"] = nullptr;
    return out;
  }
  const double cell_m = plan.frame.spec().cell_m;
  out["min_cells"] = best;
  out["min_m"] = best * cell_m;
  out["uavs"] = {best_a, best_b};
  out["t_s"] = plan.seconds(best_t);
  if (d > 0 && (best < d || conflicts > 0)) {
    warnings.push_back(fmt::format(
        "the flights come within {} of each other (UAVs {} and {} at t = {} s), less than the "
        "separation D = {}; {} conflicts were counted",
        best == 1 ? "1 cell" : fmt::format("{} cells", best), best_a, best_b, plan.seconds(best_t),
        d, conflicts));
  } else if (d == 0 && best == 0) {
    warnings.push_back(fmt::format(
        "the plan has no separation: UAVs {} and {} share a cell at t = {} s (plan with "
        "--separation D to keep them apart)",
        best_a, best_b, plan.seconds(best_t)));
  }
  return out;
}

}  // namespace hullinspect::io
