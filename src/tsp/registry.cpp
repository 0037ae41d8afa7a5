#include <fmt/format.h>

#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/tsp/segment_tsp.hpp"

namespace hullinspect::tsp {

long long tour_length(const SegmentTsp& problem, std::span<const Visit> order) {
  long long length = 0;
  grid::Cell at = problem.start;
  for (const Visit& v : order) {
    const Segment& s = problem.segments[static_cast<std::size_t>(v.segment)];
    const grid::Cell entry = v.reversed ? s.second : s.first;
    const grid::Cell exit = v.reversed ? s.first : s.second;
    length += grid::manhattan(at, entry) + grid::manhattan(entry, exit);
    at = exit;
  }
  return length;
}

namespace {
const std::vector<TspSolverInfo>& registry() {
  static const std::vector<TspSolverInfo> entries = {};
  return entries;
}
}  // namespace

std::span<const TspSolverInfo> tsp_solver_registry() { return registry(); }

std::unique_ptr<TspSolver> make_tsp_solver(std::string_view name, const OptionMap& options) {
  std::string names;
  for (const auto& info : registry()) {
    if (info.name == name) return info.make(options);
    names += (names.empty() ? "" : ", ") + info.name;
  }
  throw ParameterError("tsp_solver", fmt::format("unknown TSP solver '{}' (known: {})", name,
                                                 names.empty() ? "none" : names));
}

}  // namespace hullinspect::tsp
