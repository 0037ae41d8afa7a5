#include "end_costs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::tsp::detail {

void EndCosts::assign(const SegmentTsp& problem) {
  g_ = static_cast<int>(problem.segments.size());
  stride_ = 2 * g_ + 1;
  cost_.resize(static_cast<std::size_t>(stride_) * static_cast<std::size_t>(stride_));
  std::vector<grid::Cell>& at = cells_;
  at.resize(static_cast<std::size_t>(stride_));
  segment_total_ = 0;
  for (int l = 0; l < g_; ++l) {
    const Segment& s = problem.segments[static_cast<std::size_t>(l)];
    at[static_cast<std::size_t>(2 * l)] = s.first;
    at[static_cast<std::size_t>(2 * l + 1)] = s.second;
  }
  at[static_cast<std::size_t>(2 * g_)] = problem.start;
  if (problem.distances != nullptr && problem.distances->searched()) {
    searched_costs(*problem.distances);
  } else {
    for (int a = 0; a < stride_; ++a) {
      for (int b = 0; b < stride_; ++b) {
        cost_[static_cast<std::size_t>(a * stride_ + b)] =
            grid::manhattan(at[static_cast<std::size_t>(a)], at[static_cast<std::size_t>(b)]);
      }
    }
  }
  // The segments' own lengths from the table (distances are symmetric), not from one whole-grid
  // field per segment.
  for (int l = 0; l < g_; ++l) segment_total_ += (*this)(2 * l, 2 * l + 1);
}

void EndCosts::searched_costs(grid::DistanceService& distances) {
  // Distances are symmetric, so each search covers only the nodes after its source, and it stops
  // at the farthest of them: the ends lie close together on a large grid, the UAV possibly far
  // away, so the UAV's row is searched once (from the UAV) and no end's search reaches out to it.
  // distances_to() keeps the service's cached fields (the UAVs' next steps) as they are.
  const auto stride = static_cast<std::size_t>(stride_);
  const std::size_t uav = stride - 1;
  std::span<const grid::Cell> ends = std::span<const grid::Cell>(cells_).first(uav);
  distances.distances_to(cells_[uav], ends, std::span<int>(cost_).subspan(uav * stride, uav));
  cost_[uav * stride + uav] = 0;
  for (std::size_t a = 0; a < uav; ++a) {
    cost_[a * stride + uav] = cost_[uav * stride + a];
    cost_[a * stride + a] = 0;
    const std::size_t later = uav - a - 1;
    if (later == 0) continue;
    distances.distances_to(cells_[a], ends.subspan(a + 1),
                           std::span<int>(cost_).subspan(a * stride + a + 1, later));
    for (std::size_t b = a + 1; b < uav; ++b) cost_[b * stride + a] = cost_[a * stride + b];
  }
}

long long EndCosts::length(std::span<const int> entries) const {
  long long total = segment_total_;
  int at = start();
  for (int e : entries) {
    total += (*this)(at, e);
    at = e ^ 1;
  }
  return total;
}

namespace {
TspSolution solution_of(std::span<const int> entries, long long length, bool optimal,
                        std::chrono::steady_clock::time_point started) {
  TspSolution solution;
  solution.order.reserve(entries.size());
  for (int e : entries) solution.order.push_back(visit_of_entry(e));
  solution.length = length;
  solution.optimal = optimal;
  if (optimal) solution.lower_bound = solution.length;
  solution.seconds = seconds_since(started);
  return solution;
}
}  // namespace

TspSolution make_solution(const SegmentTsp& problem, std::span<const int> entries, bool optimal,
                          std::chrono::steady_clock::time_point started) {
  std::vector<Visit> order;
  order.reserve(entries.size());
  for (int e : entries) order.push_back(visit_of_entry(e));
  return solution_of(entries, tour_length(problem, order), optimal, started);
}

TspSolution make_solution(const EndCosts& costs, std::span<const int> entries, bool optimal,
                          std::chrono::steady_clock::time_point started) {
  return solution_of(entries, costs.length(entries), optimal, started);
}

long long simple_lower_bound(const EndCosts& costs) {
  const int ends = costs.ends();
  if (ends == 0) return 0;
  long long first_leg = std::numeric_limits<long long>::max();
  long long links = 0;  // twice the bound on the links
  int largest = 0;
  int second = 0;
  for (int v = 0; v < ends; ++v) {
    first_leg = std::min<long long>(first_leg, costs(costs.start(), v));
    int nearest = std::numeric_limits<int>::max();
    for (int w = 0; w < ends; ++w) {
      if ((w >> 1) != (v >> 1)) nearest = std::min(nearest, costs(v, w));
    }
    if (nearest == std::numeric_limits<int>::max()) nearest = 0;  // g = 1: no links
    links += nearest;
    if (nearest > largest) {
      second = largest;
      largest = nearest;
    } else if (nearest > second) {
      second = nearest;
    }
  }
  links -= largest + second;
  return costs.segment_total() + first_leg + (links + 1) / 2;
}

double seconds_since(std::chrono::steady_clock::time_point started) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

void check_solution(const SegmentTsp& problem, const TspSolution& solution, const char* solver) {
  const std::string problem_text = order_problem(problem, solution.order);
  if (!problem_text.empty()) {
    throw LogicError(
        fmt::format("tsp solver '{}' returned an invalid order: {}", solver, problem_text));
  }
  const long long length = tour_length(problem, solution.order);
  if (length != solution.length) {
    throw LogicError(fmt::format("tsp solver '{}' reported length {} for a tour of length {}",
                                 solver, solution.length, length));
  }
}

}  // namespace hullinspect::tsp::detail
