#pragma once
// Checks shared by the partitioners that take start cells (darp, transfer): starts inside the grid,
// snapped onto the hull and distinct; weights finite and > 0 on hull cells; shares finite and > 0.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/partition/partitioner.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::partition::detail {

std::string cell_text(grid::Cell c);
/// The request's hull, after checking that there is one and that the fleet (one UAV per start) has
/// 1 … min(hull cells, 32767) UAVs; ParameterError("hull" / "uavs") otherwise.
const world::HullMask& checked_fleet(const PartitionRequest& request, std::string_view partitioner);
/// Start cells as flat indices: outside the grid is a ParameterError("starts"), off the hull is
/// snapped (HullMask::snap), two UAVs on one cell (also after snapping) an error naming both.
std::vector<int> checked_starts(const world::HullMask& hull, std::span<const grid::Cell> starts);
void check_weights(const world::HullMask& hull, const grid::Grid<double>& weights);
/// The shares (equal when empty); a wrong count or a non-positive share is a ParameterError.
std::vector<double> checked_shares(std::span<const double> shares, int n);

/// What the UAVs should get: the total weight (the cell count when unweighted), each UAV's desired
/// weight (total · share / Σ shares) and the weight of "one cell" of tolerance (1, or the heaviest
/// hull cell when weighted).
struct DesiredWeights {
  double total = 0;
  double unit = 1;
  std::vector<double> desired;
};
DesiredWeights desired_weights(const world::HullMask& hull, const grid::Grid<double>& weights,
                               std::span<const double> shares);

/// The largest |region weight − desired weight| over the regions of `p`.
double largest_imbalance(const Partition& p);

}  // namespace hullinspect::partition::detail
