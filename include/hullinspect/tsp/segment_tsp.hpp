#pragma once
// The segment TSP of Part-TSP (model.md §5.3, eqs. 6–12): an open path from the UAV through every
// segment, each segment flown end to end in one of its two directions. Costs are the mission's
// distances (docs/model.md): Manhattan without no-fly zones, shortest allowed flights with them.
// Solvers (docs/tsp.md): "exact" (default, proves optimality), "dfj-iterative" (the paper's
// reference on CBC), "heuristic" (fast local search, no optimality claim).

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/core/options.hpp"
#include "hullinspect/core/registry.hpp"
#include "hullinspect/grid/cell.hpp"
#include "hullinspect/grid/distance_service.hpp"

namespace hullinspect::tsp {

struct Segment {
  grid::Cell first;   ///< node 2l+1 (left end)
  grid::Cell second;  ///< node 2l+2 (right end)
};

struct SegmentTsp {
  grid::Cell start;               ///< node 0, the UAV
  std::vector<Segment> segments;  ///< g segments
  /// The mission's distance service; null = Manhattan costs (no no-fly positions).
  grid::DistanceService* distances = nullptr;
};

/// The cost between two nodes' cells: the service's distance, or Manhattan without one.
inline int node_distance(const SegmentTsp& problem, grid::Cell a, grid::Cell b) {
  return problem.distances != nullptr ? problem.distances->distance(a, b) : grid::manhattan(a, b);
}

struct Visit {
  int segment = 0;
  bool reversed = false;  ///< flown second → first
  friend bool operator==(const Visit&, const Visit&) = default;
};

struct TspSolution {
  std::vector<Visit> order;  ///< every segment exactly once
  long long length = 0;      ///< path length including the segments themselves
  bool optimal = false;      ///< optimality proven
  /// A proven lower bound on the optimal length (= length when optimal): how far an unproven
  /// tour can be from the optimum.
  long long lower_bound = 0;
  /// The solver's own method gave up (numerical trouble) and the answer is its best tour so far,
  /// without a proof. Counted per mission (PlannerStats::tsp_fallbacks); tests assert zero.
  bool fallback = false;
  double seconds = 0;
};

/// Length of the open path start → order (segments included). Used by tests and solvers.
long long tour_length(const SegmentTsp& problem, std::span<const Visit> order);

/// Empty if `order` visits every segment of `problem` exactly once (indices in range); otherwise a
/// sentence naming the first problem found. Used by tests and by solvers' self-checks.
std::string order_problem(const SegmentTsp& problem, std::span<const Visit> order);

class TspSolver {
 public:
  virtual ~TspSolver() = default;
  /// Never returns an invalid order. Not thread-safe on one instance (solvers keep scratch space);
  /// use one solver per thread.
  virtual TspSolution solve(const SegmentTsp& problem) = 0;
};

using TspSolverInfo = RegistryEntry<TspSolver>;
using TspSolverRegistry = Registry<TspSolver>;

/// Every segment-TSP solver by name; add your own with tsp_solvers().add(…).
TspSolverRegistry& tsp_solvers();
/// A snapshot of tsp_solvers().entries().
std::vector<TspSolverInfo> tsp_solver_registry();
/// Throws ParameterError("tsp-solver", …) for an unknown name and ParameterError("<name>.<key>", …)
/// for an unknown or out-of-range option.
std::unique_ptr<TspSolver> make_tsp_solver(std::string_view name, const OptionMap& options = {});
/// The effective options of a solver (validated, defaults filled in).
OptionMap resolve_tsp_solver_options(std::string_view name, const OptionMap& options = {});
/// The default solver's name.
inline constexpr std::string_view kDefaultTspSolver = "exact";

}  // namespace hullinspect::tsp
