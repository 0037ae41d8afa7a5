#include "hullinspect/planners/flight_distances.hpp"

namespace hullinspect::planners {

void FlightDistances::build(const PlannerContext& context, grid::DistanceService& mission) {
  mission_ = &mission;
  parts_.clear();
  part_of_.clear();
  const world::Reachability* reach = context.reach;
  if (reach == nullptr || !reach->any_no_fly || reach->flight_components <= 1) return;
  const grid::Grid<int>& component = reach->flight_component;
  for (int c = 0; c < reach->flight_components; ++c) {
    grid::Grid<std::uint8_t> allowed(component.width(), component.height(), 0);
    for (int i = 0; i < allowed.size(); ++i) allowed[i] = component[i] == c ? 1 : 0;
    parts_.emplace_back(std::move(allowed));
  }
  for (const grid::Cell& s : context.starts) part_of_.push_back(component[s]);
}

grid::DistanceService& FlightDistances::of(int uav) {
  if (parts_.empty()) return *mission_;
  return parts_[static_cast<std::size_t>(part_of_[static_cast<std::size_t>(uav)])];
}

}  // namespace hullinspect::planners
