#include "support/partition_checker.hpp"

#include <fmt/format.h>

#include <cmath>

#include "hullinspect/grid/distance.hpp"

namespace hullinspect::testing {

::testing::AssertionResult valid_partition(const partition::PartitionRequest& request,
                                           const partition::Partition& p, PartitionCheck check) {
  const auto& hull = *request.hull;
  const int n = static_cast<int>(request.starts.size());
  if (p.owner.width() != hull.width() || p.owner.height() != hull.height()) {
    return ::testing::AssertionFailure() << "assignment matrix has the wrong size";
  }
  std::vector<int> sizes(static_cast<std::size_t>(n), 0);
  std::vector<double> weights(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < p.owner.size(); ++i) {
    const int k = p.owner[i];
    if (!hull.is_hull(i)) {
      if (k != -1)
        return ::testing::AssertionFailure()
               << fmt::format("non-hull cell {} assigned to {}", i, k);
      continue;
    }
    if (k < 0 || k >= n) {
      return ::testing::AssertionFailure() << fmt::format("hull cell ({}, {}) has owner {}",
                                                          p.owner.cell(i).x, p.owner.cell(i).y, k);
    }
    ++sizes[static_cast<std::size_t>(k)];
    weights[static_cast<std::size_t>(k)] += request.weights.size() > 0 ? request.weights[i] : 1.0;
  }
  grid::Grid<std::uint8_t> region(hull.width(), hull.height(), 0);
  grid::Grid<int> labels;
  grid::BfsScratch scratch;
  const double tolerance = check.tolerance >= 0 ? check.tolerance : p.tolerance;
  for (int k = 0; k < n; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    if (sizes[uk] == 0) return ::testing::AssertionFailure() << "region " << k << " is empty";
    for (int i = 0; i < region.size(); ++i) region[i] = p.owner[i] == k;
    // Across the seam of a grid that closes on itself too (request.flights).
    const int parts = grid::label_components(region, labels, scratch, request.flights);
    if (parts != 1 && check.regions_connected)
      return ::testing::AssertionFailure() << "region " << k << " has " << parts << " components";
    if (check.regions_hold_starts && p.owner[request.starts[uk]] != k) {
      return ::testing::AssertionFailure() << "region " << k << " does not hold its start cell";
    }
    if (request.seen_from.size() > 0) {
      const int own = request.seen_from[request.starts[uk]];
      for (int i : hull.cells()) {
        if (p.owner[i] != k || request.seen_from[i] < 0 || request.seen_from[i] == own) continue;
        return ::testing::AssertionFailure() << fmt::format(
                   "region {} (flight component {}) holds cell ({}, {}), seen only from flight "
                   "component {}",
                   k, own, hull.mask().cell(i).x, hull.mask().cell(i).y, request.seen_from[i]);
      }
    }
    if (uk < p.region_cells.size() && p.region_cells[uk] != sizes[uk]) {
      return ::testing::AssertionFailure() << fmt::format("region {} reports {} cells but has {}",
                                                          k, p.region_cells[uk], sizes[uk]);
    }
    if (uk < p.desired_weight.size() &&
        std::abs(weights[uk] - p.desired_weight[uk]) > tolerance + 1e-9) {
      return ::testing::AssertionFailure()
             << fmt::format("region {} weighs {} but should weigh {} ± {}", k, weights[uk],
                            p.desired_weight[uk], tolerance);
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace hullinspect::testing
