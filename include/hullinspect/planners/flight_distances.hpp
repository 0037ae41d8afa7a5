#pragma once
// The distance service each UAV of a partitioned planner flies by (docs/model.md §8, "Flight
// components"). With one flight space that is the mission's service. When no-fly zones cut the
// flight space into parts, each part gets its own service over that part's positions only, so
// that what a UAV treats as allowed — flight-row runs, viewpoints, paths, TSP costs — is what it
// can actually reach.

#include <vector>

#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/planners/planner.hpp"

namespace hullinspect::planners {

class FlightDistances {
 public:
  /// `mission`: the service every UAV uses when the flight space is one (kept by pointer; it must
  /// outlive this object). Built once at the planner's start.
  void build(const PlannerContext& context, grid::DistanceService& mission);
  /// The service of UAV k's flight component. The reference stays valid until the next build().
  grid::DistanceService& of(int uav);
  /// True when the flight space is cut into parts with UAVs in several of them.
  bool split() const { return !parts_.empty(); }

 private:
  grid::DistanceService* mission_ = nullptr;
  std::vector<grid::DistanceService> parts_;
  std::vector<int> part_of_;  // per UAV
};

}  // namespace hullinspect::planners
