#include "hullinspect/partition/stripes_partitioner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <numeric>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/grid/distance.hpp"
#include "request_checks.hpp"

namespace hullinspect::partition {

Partition StripesPartitioner::partition(const PartitionRequest& request) const {
  const auto t0 = std::chrono::steady_clock::now();
  const world::HullMask& hull = *request.hull;
  const int n = static_cast<int>(request.starts.size());
  if (n < 1) throw ParameterError("uavs", "must be at least 1 (got 0)");
  if (n > hull.cell_count()) {
    throw ParameterError(
        "uavs", fmt::format("must be at most the {} hull cells (got {})", hull.cell_count(), n));
  }
  const bool weighted = request.weights.size() > 0;
  auto weight = [&](int i) { return weighted ? request.weights[i] : 1.0; };

  // Cells in column order.
  std::vector<int> order(hull.cells());
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const grid::Cell ca = hull.mask().cell(a);
    const grid::Cell cb = hull.mask().cell(b);
    return ca.x != cb.x ? ca.x < cb.x : ca.y < cb.y;
  });
  std::vector<double> shares = request.shares;
  if (shares.empty()) shares.assign(static_cast<std::size_t>(n), 1.0);
  const double share_total = std::accumulate(shares.begin(), shares.end(), 0.0);
  double total = 0;
  for (int i : order) total += weight(i);

  // UAVs ordered by their start's x give the band order.
  std::vector<int> uav_of_band(static_cast<std::size_t>(n));
  std::iota(uav_of_band.begin(), uav_of_band.end(), 0);
  std::stable_sort(uav_of_band.begin(), uav_of_band.end(), [&](int a, int b) {
    const auto& sa = request.starts[static_cast<std::size_t>(a)];
    const auto& sb = request.starts[static_cast<std::size_t>(b)];
    return sa.x != sb.x ? sa.x < sb.x : sa.y < sb.y;
  });

  Partition out;
  out.owner = grid::Grid<std::int16_t>(hull.width(), hull.height(), -1);
  out.region_cells.assign(static_cast<std::size_t>(n), 0);
  out.region_weight.assign(static_cast<std::size_t>(n), 0.0);
  out.desired_weight.assign(static_cast<std::size_t>(n), 0.0);
  for (int k = 0; k < n; ++k) {
    out.desired_weight[static_cast<std::size_t>(k)] =
        total * shares[static_cast<std::size_t>(k)] / share_total;
  }
  std::size_t next = 0;
  double cumulative_target = 0;
  double cumulative = 0;
  for (int band = 0; band < n; ++band) {
    const int k = uav_of_band[static_cast<std::size_t>(band)];
    cumulative_target += out.desired_weight[static_cast<std::size_t>(k)];
    const std::size_t remaining_bands = static_cast<std::size_t>(n - band - 1);
    // Take cells while it brings the band closer to its cumulative target; leave one per later
    // band.
    bool took_one = false;
    while (next + remaining_bands < order.size()) {
      const double w = weight(order[next]);
      const bool last_band = band == n - 1;
      if (!last_band && took_one &&
          std::abs(cumulative + w - cumulative_target) > std::abs(cumulative - cumulative_target)) {
        break;
      }
      out.owner[order[next]] = static_cast<std::int16_t>(k);
      out.region_cells[static_cast<std::size_t>(k)] += 1;
      out.region_weight[static_cast<std::size_t>(k)] += w;
      cumulative += w;
      took_one = true;
      ++next;
    }
  }
  // Connectivity check: each band must be one 4-connected piece (across the seam of a grid that
  // closes on itself too).
  grid::Grid<std::uint8_t> in_region(hull.width(), hull.height(), 0);
  grid::Grid<int> labels;
  grid::BfsScratch scratch;
  for (int k = 0; k < n; ++k) {
    for (int i : hull.cells()) in_region[i] = out.owner[i] == k;
    if (grid::label_components(in_region, labels, scratch, request.flights) != 1) {
      throw Error(
          fmt::format("stripes: band of UAV {} is not 4-connected on hull '{}'; use the darp "
                      "partitioner for this hull",
                      k, hull.source()));
    }
  }
  out.tolerance = detail::largest_imbalance(out);
  out.converged = true;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace hullinspect::partition
