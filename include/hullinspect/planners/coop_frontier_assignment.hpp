#pragma once
// Frontier utilities and the greedy robot–frontier assignment of the Coop-Frontier planner
// (model.md §5.4; paper eqs. 13 and 15–17).

#include <span>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/grid/distance_service.hpp"

namespace hullinspect::planners {

/// U_f = α / d_HP + (1 − α) / d_C (eq. 13). Each distance is to the nearest member of its set, or
/// grid::kUnreachable (or any value < 0) when that set is empty: the term then contributes 0. Both
/// distances are clamped to at least 1 (model.md §5.4: d_C = max(1, ·); d_HP ≥ 1 on a frontier
/// anyway).
double frontier_utility(double alpha, int d_hp, int d_c);

/// P(d) of eq. 17: d / (2·s2) for d < 2·s2, else 1.
double utility_reduction(double d, int s2);

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

  /// The pairs of the last assign() in the order they were chosen.
  std::span<const Pick> picks() const { return picks_; }
  /// U(f|f_1…f_m) of every frontier after the last assign() (all picks applied).
  std::span<const double> reduced_utility() const { return reduced_; }

 private:
  void reduce_around(std::span<const grid::Cell> frontiers, grid::Cell assigned);
  /// The best frontier of one robot under the current reduced utilities (ties: lowest (y, x)).
  Pick best_for(std::span<const grid::Cell> frontiers, int robot, grid::Cell at) const;

  double beta_ = 1.0;
  int s2_ = 7;
  grid::DistanceService* distances_ = nullptr;
  std::span<grid::DistanceService* const> robot_distances_;
  int robot_half_ = 0;
  std::vector<double> travel_term_;  // β / max(1, d) for d = 0 … max_distance
  std::vector<double> reduction_;    // P(√q) for squared distances q < (2·s2)²
  std::vector<double> reduced_;
  std::vector<unsigned char> assigned_;
  std::vector<Pick> picks_;
  std::vector<Pick> best_;  // per robot
};

}  // namespace hullinspect::planners
