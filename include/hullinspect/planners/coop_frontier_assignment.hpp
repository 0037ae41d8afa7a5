#pragma once
// Frontier utilities and the greedy robot–frontier assignment of the Coop-Frontier planner
// (model.md §5.4; paper eqs. 13 and 15–17).

#include <span>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/planners/coop_frontier_cell_set.hpp"

namespace hullinspect::planners {

/// U_f = α / d_HP + (1 − α) / d_C (eq. 13). Each distance is to the nearest member of its set, or
/// grid::kUnreachable (or any value < 0) when that set is empty: the term then contributes 0. Both
/// distances are clamped to at least 1 (model.md §5.4: d_C = max(1, ·); d_HP ≥ 1 on a frontier
/// anyway).
double frontier_utility(double alpha, int d_hp, int d_c);

/// P(d) of eq. 17: d / (2·s2) for d < 2·s2, else 1.
double utility_reduction(double d, int s2);

/// U_f of the frontier at a position of the frontier set, read only for the frontiers an
/// assignment looks at.
class FrontierUtilities {
 public:
  virtual ~FrontierUtilities() = default;
  virtual double utility(int position) const = 0;
  /// ≥ U_f + β / max(1, d) for every frontier at a Manhattan distance d ≥ m from `at`.
  virtual double score_ceiling(grid::Cell at, int m, double beta) const = 0;
};

/// The greedy assignment of eqs. 15–17. Reusable: after the first calls it allocates nothing.
class FrontierAssigner {
 public:
  /// One (robot, frontier) pair in the order it was chosen, with its eq. 15 score.
  struct Pick {
    int robot = -1;     ///< position in the `robots` argument
    int frontier = -1;  ///< position in the `frontiers` argument
    double score = 0;   ///< U(f|f_1…f_m) + β / max(1, d(r, f))
  };

  /// β of eq. 15, s2 of eq. 17, and the largest Manhattan distance that can occur (grid width +
  /// height) so the β / max(1, d) terms come from a table.
  void configure(double beta, int s2, int max_distance);
  /// Reserves room for up to `frontiers` frontiers and `robots` robots, so assign() never
  /// allocates.
  void reserve(int frontiers, int robots);
  /// d(r, f) from the mission's distance service (shortest allowed flights); null: Manhattan.
  void set_distances(grid::DistanceService* distances) { distances_ = distances; }
  /// No-fly zones that cut the flight space into parts (docs/model.md §8): for the next assign(),
  /// robot r's d(r, f) comes from services[r] (the service of its own part) and r only takes
  /// frontiers that service has a viewpoint for at footprint half-width `half` (a robot with none
  /// gets −1). Empty: every robot uses set_distances()' service and may take any frontier.
  void set_robot_distances(std::span<grid::DistanceService* const> services, int half) {
    robot_distances_ = services;
    robot_half_ = half;
  }

  /// Assigns one frontier to every robot. `frontiers` are the cells of F with their utilities U_f
  /// (eq. 13) in `utility`; `held` are the targets other EXPLORE UAVs keep, which reduce U by eq.
  /// 16 before anything is chosen; `robots` are the positions of the UAVs that need a target, in
  /// increasing UAV id. Then, |robots| times: pick (r*, f*) = argmax over unassigned robots r and
  /// all f of U(f|f_1…f_m) + β / max(1, d(r, f)) with d the Manhattan distance (ties: first robot,
  /// then lowest (y, x) of f), assign it, and multiply every U by P(‖f − f*‖) (Euclidean). A
  /// frontier may go to several robots when the β term outweighs its reduced utility. Writes the
  /// position in `frontiers` chosen for robot r to chosen[r] (−1 when `frontiers` is empty).
  void assign(std::span<const grid::Cell> frontiers, std::span<const double> utility,
              std::span<const grid::Cell> held, std::span<const grid::Cell> robots,
              std::span<int> chosen);
  /// The same assignment (the same pairs, ties and scores) over the frontier set `frontiers`
  /// (positions as in its cells()), reading U_f only where needed: a robot's best frontier is
  /// searched in rings of growing Manhattan distance m around it, and the search stops at the
  /// ring from which even utilities.score_ceiling(robot, m, β) (≥ any U_f + β / d(r, f) there:
  /// shortest flights are no shorter than the Manhattan distance) is below the best score found, or
  /// falls back to a scan of F once the rings have covered more than half as many cells as F
  /// holds. The cost then follows the frontiers near the robot rather than |F|. Robots with their
  /// own distance services (set_robot_distances), and hulls whose seam is linked (a flight across
  /// it is shorter than the Manhattan distance), scan F. reduced_utility() is not filled.
  void assign(const IndexedCellSet& frontiers, const FrontierUtilities& utilities,
              std::span<const grid::Cell> held, std::span<const grid::Cell> robots,
              std::span<int> chosen);

  /// The pairs of the last assign() in the order they were chosen.
  std::span<const Pick> picks() const { return picks_; }
  /// U(f|f_1…f_m) of every frontier after the last assign() of utilities given as a span (all
  /// picks applied).
  std::span<const double> reduced_utility() const { return reduced_; }

 private:
  /// The greedy rounds over the frontiers of the current call (frontiers_, utilities_, held_).
  void run(std::span<const grid::Cell> robots, std::span<int> chosen);
  /// U(f|f_1…f_m) of the frontier at `position` under the picks so far: U_f times P for every
  /// held target and then every pick, in that order (as if each had been applied to all of F).
  double reduced(int position);
  /// The best frontier of one robot under the current reduced utilities (ties: lowest (y, x)).
  Pick best_for(int robot, grid::Cell at);
  /// best_for() by a scan of every frontier.
  Pick scan(int robot, grid::Cell at, grid::DistanceService* distances,
            const grid::Grid<int>* field);
  /// best_for() by rings of growing Manhattan distance around `at` (frontiers given as a set).
  Pick rings(int robot, grid::Cell at, const grid::Grid<int>* field);
  /// The score of (robot, frontier at position j, flight distance d) against `best`.
  void consider(Pick& best, int robot, int j, std::size_t d);
  /// P(‖a − b‖) of eq. 17 (1 beyond its radius).
  double reduction(grid::Cell a, grid::Cell b) const;

  double beta_ = 1.0;
  int s2_ = 7;
  grid::DistanceService* distances_ = nullptr;
  std::span<grid::DistanceService* const> robot_distances_;
  int robot_half_ = 0;
  std::vector<double> travel_term_;  // β / max(1, d) for d = 0 … max_distance
  std::vector<double> reduction_;    // P(√q) for squared distances q < (2·s2)²
  // The current call.
  std::span<const grid::Cell> frontiers_;
  const IndexedCellSet* set_ = nullptr;  // null: scan
  const FrontierUtilities* utilities_ = nullptr;
  std::span<const grid::Cell> held_;
  // Per frontier position, computed when first read in a call: stamp_ = epoch_, the reduced value
  // and how many picks it has had.
  std::vector<double> reduced_;
  std::vector<unsigned> stamp_;
  std::vector<std::size_t> applied_;
  unsigned epoch_ = 0;
  std::vector<unsigned char> assigned_;
  std::vector<Pick> picks_;
  std::vector<Pick> best_;  // per robot
};

}  // namespace hullinspect::planners
