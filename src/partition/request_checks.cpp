#include "request_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/plural.hpp"

namespace hullinspect::partition::detail {

std::string cell_text(grid::Cell c) {
  return fmt::format("({}, {})", c.x, c.y);
}

const world::HullMask& checked_fleet(const PartitionRequest& request,
                                     std::string_view partitioner) {
  if (request.hull == nullptr) {
    throw ParameterError("hull", fmt::format("no hull given to the {} partitioner", partitioner));
  }
  const world::HullMask& hull = *request.hull;
  const int n = static_cast<int>(request.starts.size());
  if (n < 1) throw ParameterError("uavs", "must be at least 1 (got 0)");
  // Regions are numbered in int16 owner grids.
  const int limit =
      std::min(hull.cell_count(), static_cast<int>(std::numeric_limits<std::int16_t>::max()));
  if (n > limit) {
    throw ParameterError("uavs", fmt::format("must be at most {} for a hull of {} cells (got {})",
                                             limit, hull.cell_count(), n));
  }
  return hull;
}

std::vector<int> checked_starts(const world::HullMask& hull, std::span<const grid::Cell> starts) {
  std::vector<int> index;
  std::vector<grid::Cell> snapped;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const grid::Cell c = starts[k];
    if (!hull.mask().contains(c)) {
      throw ParameterError(
          "starts", fmt::format("start cell {} of UAV {} is outside the {} × {} grid", cell_text(c),
                                k, hull.width(), hull.height()));
    }
    snapped.push_back(hull.is_hull(c) ? c : hull.snap(c));
  }
  for (std::size_t k = 0; k < snapped.size(); ++k) {
    for (std::size_t other = 0; other < k; ++other) {
      if (snapped[other] != snapped[k]) continue;
      const bool moved = snapped[k] != starts[k] || snapped[other] != starts[other];
      throw ParameterError(
          "starts", fmt::format("UAVs {} and {} both start on cell {}{}; every UAV needs its own "
                                "start cell",
                                other, k, cell_text(snapped[k]),
                                moved ? " (after snapping to the nearest hull cell)" : ""));
    }
    index.push_back(hull.mask().index(snapped[k]));
  }
  return index;
}

void check_weights(const world::HullMask& hull, const grid::Grid<double>& weights) {
  if (weights.width() != hull.width() || weights.height() != hull.height()) {
    throw ParameterError("weights",
                         fmt::format("grid is {} × {} but the hull is {} × {}", weights.width(),
                                     weights.height(), hull.width(), hull.height()));
  }
  for (int i : hull.cells()) {
    const double w = weights[i];
    if (!(w > 0) || !std::isfinite(w)) {
      throw ParameterError("weights", fmt::format("hull cell {} has weight {}; weights must be "
                                                  "finite and > 0",
                                                  cell_text(hull.mask().cell(i)), w));
    }
  }
}

std::vector<double> checked_shares(std::span<const double> shares, int n) {
  if (shares.empty()) return std::vector<double>(static_cast<std::size_t>(n), 1.0);
  if (static_cast<int>(shares.size()) != n) {
    throw ParameterError(
        "shares",
        fmt::format("gives {} for {}", plural(static_cast<long long>(shares.size()), "share"),
                    plural(n, "UAV")));
  }
  for (std::size_t k = 0; k < shares.size(); ++k) {
    if (!(shares[k] > 0) || !std::isfinite(shares[k])) {
      throw ParameterError("shares", fmt::format("share of UAV {} is {}; shares must be finite and "
                                                 "> 0",
                                                 k, shares[k]));
    }
  }
  return {shares.begin(), shares.end()};
}

double largest_imbalance(const Partition& p) {
  double worst = 0;
  for (std::size_t k = 0; k < p.region_weight.size() && k < p.desired_weight.size(); ++k) {
    worst = std::max(worst, std::abs(p.region_weight[k] - p.desired_weight[k]));
  }
  return worst;
}

DesiredWeights desired_weights(const world::HullMask& hull, const grid::Grid<double>& weights,
                               std::span<const double> shares) {
  DesiredWeights d;
  if (weights.size() > 0) {
    d.unit = 0;
    for (int i : hull.cells()) {
      d.total += weights[i];
      d.unit = std::max(d.unit, weights[i]);
    }
  } else {
    d.total = hull.cell_count();
  }
  const double share_total = std::accumulate(shares.begin(), shares.end(), 0.0);
  d.desired.reserve(shares.size());
  for (const double share : shares) d.desired.push_back(d.total * share / share_total);
  return d;
}

}  // namespace hullinspect::partition::detail
