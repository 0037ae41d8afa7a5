#pragma once
// The segment TSP of Part-TSP (SPEC §5.3, eqs. 6–12): an open path from the UAV through every
// segment, each segment flown end to end in one of its two directions, Manhattan costs.

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/core/options.hpp"
#include "hullinspect/grid/cell.hpp"

namespace hullinspect::tsp {

struct Segment {
  grid::Cell first;   ///< node 2l+1 (left end)
  grid::Cell second;  ///< node 2l+2 (right end)
};

struct SegmentTsp {
  grid::Cell start;               ///< node 0, the UAV
  std::vector<Segment> segments;  ///< g segments
};

struct Visit {
  int segment = 0;
  bool reversed = false;  ///< flown second → first
};

struct TspSolution {
  std::vector<Visit> order;  ///< every segment exactly once
  long long length = 0;      ///< path length including the segments themselves
  bool optimal = false;      ///< optimality proven
  double seconds = 0;
};

/// Length of the open path start → order (segments included). Used by tests and solvers.
long long tour_length(const SegmentTsp& problem, std::span<const Visit> order);

class TspSolver {
 public:
  virtual ~TspSolver() = default;
  virtual TspSolution solve(const SegmentTsp& problem) = 0;
};

struct TspSolverInfo {
  std::string name;
  std::string description;
  std::vector<OptionSpec> options;
  std::unique_ptr<TspSolver> (*make)(const OptionMap& options);
};

std::span<const TspSolverInfo> tsp_solver_registry();
/// Throws ParameterError("tsp_solver", …) for an unknown name.
std::unique_ptr<TspSolver> make_tsp_solver(std::string_view name, const OptionMap& options = {});

}  // namespace hullinspect::tsp
