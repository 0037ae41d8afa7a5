#pragma once

#include <memory>
#include <string>
#include <vector>

#include "hullinspect/planners/flight_distances.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/planners/waypoint_follower.hpp"

namespace hullinspect::planners {

struct LawnmowerOptions {
  std::string partitioner{partition::kDefaultPartitioner};  ///< by name
  OptionMap partitioner_options;
  std::uint64_t partition_seed = 0;  ///< seed of the partitioner (not of the instance)
  // Beyond the paper, off by default (prior_weights.hpp, docs/model.md §5.5).
  bool prior_weights = false;    ///< partition weighted by the expected work per cell
  bool prior_statistics = true;  ///< those weights use the scenario's p_TP, p_FP
};

/// The baseline of model.md §5.2: descend to z = 1 once, then sweep the UAV's region strip by strip
/// (strips of s1 rows from the bottom, flown along their centre rows, bottom to top, each from its
/// nearer end). Ignores the prior and everything sensed. With no-fly zones its route goes around
/// them (lawnmower_no_fly.hpp).
class LawnmowerPlanner final : public Planner {
 public:
  explicit LawnmowerPlanner(LawnmowerOptions options) : options_(std::move(options)) {}
  void start(const PlannerContext& context) override;
  void decide(const sim::PlannerView& view, std::span<sim::Action> actions) override;
  const partition::Partition* partition() const override { return partition_.get(); }
  /// Every working UAV has flown its whole sweep.
  bool idle(const sim::PlannerView& view) const override;
  void annotate(AnnotationSink& sink) const override;

  /// The sweep of one region: the waypoints (strip ends) from `from`.
  static std::vector<grid::Cell> sweep(const grid::Grid<std::int16_t>& owner, int uav, int s1,
                                       grid::Cell from);

 private:
  LawnmowerOptions options_;
  std::shared_ptr<const partition::Partition> partition_;
  std::vector<WaypointFollower> followers_;
  std::vector<sim::UavState> last_;
  grid::DistanceService own_distances_;
  FlightDistances flights_;  // per UAV: the service of its flight component
  // With no-fly zones only: the waypoints of the z = 2 leg still to come, and whether it began.
  std::vector<std::vector<grid::Cell>> climb_;
  std::vector<std::uint8_t> climbed_;
};

}  // namespace hullinspect::planners
