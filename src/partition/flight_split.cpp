#include "hullinspect/partition/flight_split.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <limits>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/grid/distance.hpp"
#include "hullinspect/grid/distance_service.hpp"
#include "request_checks.hpp"

namespace hullinspect::partition {

namespace {

// "UAV 3" or "UAVs 0, 2".
std::string uav_list(const std::vector<int>& uavs) {
  std::string text = uavs.size() == 1 ? "UAV " : "UAVs ";
  for (std::size_t j = 0; j < uavs.size(); ++j) text += fmt::format("{}{}", j ? ", " : "", uavs[j]);
  return text;
}

// Each hull cell's flight component (the one that sees it, if it holds a UAV), else -1.
grid::Grid<int> seen_components(const world::HullMask& hull, const grid::Grid<int>& seen_from,
                                const std::vector<bool>& has_uav) {
  grid::Grid<int> label(hull.width(), hull.height(), -1);
  for (int i : hull.cells()) {
    const int c = seen_from[i];
    if (c >= 0 && c < static_cast<int>(has_uav.size()) && has_uav[static_cast<std::size_t>(c)])
      label[i] = c;
  }
  return label;
}

// Gives every hull cell without an owner the owner of the nearest owned cell over hull cells
// (breadth-first from the owned cells in index order, so ties are deterministic and each region
// stays as connected as it was; across the seam of `flights` too). Calls give(i, k) for each.
template <class Give>
void attach_unowned(const world::HullMask& hull, const grid::Grid<std::int16_t>& owner,
                    const grid::EdgeSteps& flights, Give&& give) {
  std::vector<int> queue;
  for (int i : hull.cells()) {
    if (owner[i] >= 0) queue.push_back(i);
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const grid::Cell at = hull.mask().cell(queue[head]);
    const int k = owner[queue[head]];
    for (int d = 0; d < 4; ++d) {
      const grid::Cell c = grid::neighbour(at, d, hull.width(), hull.height(), flights);
      if (c == grid::kNoCell || !hull.is_hull(c) || owner[c] >= 0) continue;
      give(hull.mask().index(c), k);
      queue.push_back(hull.mask().index(c));
    }
  }
}

// The request's allowed positions restricted to the flight part holding `start` (all of them
// when the request has none).
grid::Grid<std::uint8_t> component_positions(const grid::Grid<std::uint8_t>& allowed,
                                             const grid::Grid<int>& parts, grid::Cell start) {
  if (allowed.size() == 0) return {};
  grid::Grid<std::uint8_t> out(allowed.width(), allowed.height(), 0);
  const int part = parts[start];
  for (int i = 0; i < out.size(); ++i) out[i] = part >= 0 && parts[i] == part ? 1 : 0;
  return out;
}

}  // namespace

std::vector<int> start_components(const PartitionRequest& request) {
  if (request.seen_from.size() == 0 || request.hull == nullptr) return {};
  const world::HullMask& hull = *request.hull;
  if (request.seen_from.width() != hull.width() || request.seen_from.height() != hull.height()) {
    throw LogicError(fmt::format("partition request: seen_from is {} × {} but the hull is {} × {}",
                                 request.seen_from.width(), request.seen_from.height(),
                                 hull.width(), hull.height()));
  }
  std::vector<int> out;
  for (int s : detail::checked_starts(hull, request.starts)) out.push_back(request.seen_from[s]);
  return out;
}

Partition partition_per_flight_component(const PartitionRequest& request,
                                         const PartitionOne& partition_one) {
  const std::vector<int> component = start_components(request);
  if (component.empty()) return partition_one(request);
  const bool one_space =
      std::all_of(component.begin(), component.end(), [&](int c) { return c == component[0]; }) &&
      std::all_of(request.hull->cells().begin(), request.hull->cells().end(),
                  [&](int i) { return request.seen_from[i] >= 0; });
  if (one_space) return partition_one(request);

  const auto t0 = std::chrono::steady_clock::now();
  const world::HullMask& hull = *request.hull;
  const int n = static_cast<int>(component.size());
  const std::vector<int> start = detail::checked_starts(hull, request.starts);
  int components = 0;
  for (int k = 0; k < n; ++k) {
    const int c = component[static_cast<std::size_t>(k)];
    if (c < 0) {
      throw LogicError(
          fmt::format("partition request: the start of UAV {} is seen from no flight "
                      "component",
                      k));
    }
    components = std::max(components, c + 1);
  }
  std::vector<bool> has_uav(static_cast<std::size_t>(components), false);
  for (int c : component) has_uav[static_cast<std::size_t>(c)] = true;
  const bool weighted = request.weights.size() > 0;
  if (weighted) detail::check_weights(hull, request.weights);
  const std::vector<double> shares = detail::checked_shares(request.shares, n);
  auto weight = [&](int i) { return weighted ? request.weights[i] : 1.0; };

  const grid::Grid<int> label = seen_components(hull, request.seen_from, has_uav);
  // Flight parts of the allowed positions, joined across the seam of a grid that closes on itself
  // as the reachability's flight components are.
  grid::Grid<int> parts;
  grid::BfsScratch scratch;
  if (request.allowed.size() > 0)
    grid::label_components(request.allowed, parts, scratch, request.flights);
  grid::DistanceService flights =
      !request.flights.empty()
          ? grid::DistanceService(request.allowed.size() > 0
                                      ? request.allowed
                                      : grid::Grid<std::uint8_t>(hull.width(), hull.height(), 1),
                                  request.flights, /*cached_fields=*/1)
      : request.allowed.size() > 0 ? grid::DistanceService(request.allowed, /*cached_fields=*/1)
                                   : grid::DistanceService(hull.width(), hull.height());

  Partition out;
  out.owner = grid::Grid<std::int16_t>(hull.width(), hull.height(), -1);
  out.region_cells.assign(static_cast<std::size_t>(n), 0);
  out.region_weight.assign(static_cast<std::size_t>(n), 0.0);
  out.desired_weight.assign(static_cast<std::size_t>(n), 0.0);
  out.tolerance = 0;
  auto give = [&](int i, int k) {
    out.owner[i] = static_cast<std::int16_t>(k);
    out.region_cells[static_cast<std::size_t>(k)] += 1;
    out.region_weight[static_cast<std::size_t>(k)] += weight(i);
  };

  grid::Grid<std::uint8_t> mask(hull.width(), hull.height(), 0);
  grid::Grid<int> pieces;
  for (int c = 0; c < components; ++c) {
    for (int i = 0; i < mask.size(); ++i) mask[i] = label[i] == c ? 1 : 0;
    // Pieces in the grid's own plane: each is partitioned as a hull of its own, which must be
    // 4-connected without the seam; pieces that meet only across it are joined by the orphans'
    // rule below.
    const int piece_count = grid::label_components(mask, pieces, scratch);
    std::vector<std::vector<int>> uavs_of(static_cast<std::size_t>(piece_count));
    std::vector<std::vector<int>> cells_of(static_cast<std::size_t>(piece_count));
    for (int i : hull.cells()) {
      if (pieces[i] >= 0) cells_of[static_cast<std::size_t>(pieces[i])].push_back(i);
    }
    for (int k = 0; k < n; ++k) {
      if (component[static_cast<std::size_t>(k)] != c) continue;
      uavs_of[static_cast<std::size_t>(pieces[start[static_cast<std::size_t>(k)]])].push_back(k);
    }
    std::vector<int> orphans;  // pieces without a start
    for (int p = 0; p < piece_count; ++p) {
      const std::vector<int>& uavs = uavs_of[static_cast<std::size_t>(p)];
      const std::vector<int>& cells = cells_of[static_cast<std::size_t>(p)];
      if (uavs.empty()) {
        orphans.push_back(p);
        continue;
      }
      if (uavs.size() == 1) {
        for (int i : cells) {
          give(i, uavs[0]);
          out.desired_weight[static_cast<std::size_t>(uavs[0])] += weight(i);
        }
        continue;
      }
      grid::Grid<std::uint8_t> piece_mask(hull.width(), hull.height(), 0);
      for (int i : cells) piece_mask[i] = 1;
      const world::HullMask piece(std::move(piece_mask), hull.source());
      PartitionRequest sub;
      sub.hull = &piece;
      sub.weights = request.weights;
      sub.seed = request.seed;
      for (int k : uavs) {
        sub.starts.push_back(hull.mask().cell(start[static_cast<std::size_t>(k)]));
        if (!request.shares.empty()) sub.shares.push_back(shares[static_cast<std::size_t>(k)]);
      }
      sub.allowed = component_positions(request.allowed, parts, sub.starts[0]);
      sub.flights = request.flights;
      Partition part = partition_one(sub);
      for (int i : cells) give(i, uavs[static_cast<std::size_t>(part.owner[i])]);
      for (std::size_t j = 0; j < uavs.size(); ++j) {
        out.desired_weight[static_cast<std::size_t>(uavs[j])] += part.desired_weight[j];
      }
      out.iterations += part.iterations;
      out.converged = out.converged && part.converged;
      out.tolerance = std::max(out.tolerance, part.tolerance);
      for (const std::string& w : part.warnings) {
        out.warnings.push_back(fmt::format("flight component {} ({}): {}", c, uav_list(uavs), w));
      }
      if (out.fallback.empty()) out.fallback = part.fallback;
    }
    // Each piece without a start goes whole to the UAV of this component with the shortest flight
    // to one of its cells (ties: lowest id).
    std::vector<int> best_uav(orphans.size(), -1);
    std::vector<int> best_distance(orphans.size(), std::numeric_limits<int>::max());
    for (int k = 0; k < n && !orphans.empty(); ++k) {
      if (component[static_cast<std::size_t>(k)] != c) continue;
      const grid::Grid<int>& field =
          flights.field(hull.mask().cell(start[static_cast<std::size_t>(k)]));
      for (std::size_t o = 0; o < orphans.size(); ++o) {
        int d = std::numeric_limits<int>::max();
        for (int i : cells_of[static_cast<std::size_t>(orphans[o])]) d = std::min(d, field[i]);
        if (d < best_distance[o]) {
          best_distance[o] = d;
          best_uav[o] = k;
        }
      }
    }
    for (std::size_t o = 0; o < orphans.size(); ++o) {
      for (int i : cells_of[static_cast<std::size_t>(orphans[o])]) {
        give(i, best_uav[o]);
        out.desired_weight[static_cast<std::size_t>(best_uav[o])] += weight(i);
      }
    }
  }
  // Cells no one sees (excluded from the metrics) still need an owner.
  attach_unowned(hull, out.owner, request.flights, [&](int i, int k) {
    give(i, k);
    out.desired_weight[static_cast<std::size_t>(k)] += weight(i);
  });
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace hullinspect::partition
