#include "hullinspect/tsp/segment_tsp.hpp"

#include <fmt/format.h>

#include <vector>

namespace hullinspect::tsp {

long long tour_length(const SegmentTsp& problem, std::span<const Visit> order) {
  long long length = 0;
  grid::Cell at = problem.start;
  for (const Visit& v : order) {
    const Segment& s = problem.segments[static_cast<std::size_t>(v.segment)];
    const grid::Cell entry = v.reversed ? s.second : s.first;
    const grid::Cell exit = v.reversed ? s.first : s.second;
    length += node_distance(problem, at, entry) + node_distance(problem, entry, exit);
    at = exit;
  }
  return length;
}

std::string order_problem(const SegmentTsp& problem, std::span<const Visit> order) {
  const std::size_t g = problem.segments.size();
  if (order.size() != g) {
    return fmt::format("the order has {} visits for {} segments", order.size(), g);
  }
  std::vector<bool> seen(g, false);
  for (std::size_t i = 0; i < order.size(); ++i) {
    const int s = order[i].segment;
    if (s < 0 || static_cast<std::size_t>(s) >= g) {
      return fmt::format("visit {} names segment {}, outside [0, {})", i, s, g);
    }
    if (seen[static_cast<std::size_t>(s)]) {
      return fmt::format("visit {} repeats segment {}", i, s);
    }
    seen[static_cast<std::size_t>(s)] = true;
  }
  return {};
}

}  // namespace hullinspect::tsp
