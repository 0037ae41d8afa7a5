#include "hullinspect/partition/darp_partitioner.hpp"
#include "hullinspect/core/plural.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include "darp_workspace.hpp"
#include "hullinspect/core/errors.hpp"
#include "request_checks.hpp"

namespace hullinspect::partition {

namespace {

// The evaluation matrices take n × N floats; refuse sizes that cannot be meant (≈ 1 GiB).
constexpr long long kMaxMatrixEntries = 1LL << 28;

bool divides_exactly(std::span<const double> desired, double unit) {
  return std::all_of(desired.begin(), desired.end(), [&](double d) {
    const double cells = d / unit;
    return std::abs(cells - std::round(cells)) <= 1e-9 * std::max(1.0, cells);
  });
}

}  // namespace

using detail::check_weights;
using detail::checked_shares;
using detail::checked_starts;
using detail::desired_weights;
using detail::DesiredWeights;

const Params<DarpOptions>& darp_params() {
  static const Params<DarpOptions> params = [] {
    Params<DarpOptions> p("darp");
    p.integer("iteration-limit", &DarpOptions::iteration_limit, 1, 1'000'000,
              "iterations at the first tolerance; halves each time the tolerance grows")
        .integer("work-budget", &DarpOptions::work_budget, 0, 1'000'000,
                 "millions of (UAV, cell) evaluations per tolerance: caps the iterations at "
                 "budget*1e6/(n*cells); 0 = no cap")
        .number("cc", &DarpOptions::cc, 0.0, 0.5,
                "connectivity correction variation: factors in [1-cc, 1+cc]")
        .number("rl", &DarpOptions::rl, 0.0, 0.1, "random level: factors in [1-rl, 1+rl]")
        .integer("max-discrepancy", &DarpOptions::max_discrepancy, 0, 1'000'000,
                 "largest tolerance (cells) before falling back to the best connected partition")
        .number("fairness-gain", &DarpOptions::fairness_gain, 1e-6, 10.0,
                "largest gain g of the fairness multiplier exp(g * (w - d) / d)")
        .number("gain-growth", &DarpOptions::gain_growth, 1.0, 10.0,
                "gain factor after a step that kept the sign")
        .number("gain-shrink", &DarpOptions::gain_shrink, 0.01, 1.0,
                "gain factor after a step that flipped it")
        .flag("repair-fallback", &DarpOptions::repair_fallback,
              "fallback may repair the best-balanced iterate into a connected partition");
    return p;
  }();
  return params;
}

std::vector<ParamSpec> darp_option_specs() {
  return darp_params().specs();
}

DarpOptions read_darp_options(const OptionMap& options) {
  return darp_params().read(options);
}

DarpPartitioner::DarpPartitioner(DarpOptions options) : options_(options) {
  auto check = [](bool ok, const char* name, const std::string& problem) {
    if (!ok) throw ParameterError(std::string("darp.") + name, problem);
  };
  check(options_.iteration_limit >= 1, "iteration-limit", "must be at least 1");
  check(options_.work_budget >= 0, "work-budget", "must be at least 0");
  check(options_.cc >= 0 && options_.cc <= 0.5, "cc", "must be in [0, 0.5]");
  check(options_.rl >= 0 && options_.rl <= 0.1, "rl", "must be in [0, 0.1]");
  check(options_.max_discrepancy >= 0, "max-discrepancy", "must be at least 0");
  check(options_.fairness_gain > 0 && options_.fairness_gain <= 10, "fairness-gain",
        "must be in (0, 10]");
  check(options_.gain_growth >= 1 && options_.gain_growth <= 10, "gain-growth",
        "must be in [1, 10]");
  check(options_.gain_shrink > 0 && options_.gain_shrink <= 1, "gain-shrink", "must be in (0, 1]");
}

Partition DarpPartitioner::partition(const PartitionRequest& request) const {
  const auto t0 = std::chrono::steady_clock::now();
  const world::HullMask& hull = detail::checked_fleet(request, "darp");
  const int n = static_cast<int>(request.starts.size());
  if (static_cast<long long>(n) * hull.cell_count() > kMaxMatrixEntries) {
    throw ParameterError(
        "uavs", fmt::format("{} UAVs on {} hull cells need {} evaluation entries; "
                            "at most {} are supported",
                            n, hull.cell_count(), static_cast<long long>(n) * hull.cell_count(),
                            kMaxMatrixEntries));
  }
  const std::vector<int> starts = checked_starts(hull, request.starts);
  const bool weighted = request.weights.size() > 0;
  if (weighted) check_weights(hull, request.weights);
  const std::vector<double> shares = checked_shares(request.shares, n);

  DesiredWeights want = desired_weights(hull, request.weights, shares);
  const double total = want.total;
  const double unit = want.unit;  // one cell of tolerance
  Partition out;
  out.desired_weight = std::move(want.desired);
  out.owner = grid::Grid<std::int16_t>(hull.width(), hull.height(), -1);
  auto finish = [&]() {
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };

  if (n == 1) {
    for (int i : hull.cells()) out.owner[i] = 0;
    out.region_cells = {hull.cell_count()};
    out.region_weight = {total};
    out.tolerance = 0;
    return finish();
  }

  detail::DarpWorkspace ws(hull, starts, weighted ? &request.weights : nullptr, out.desired_weight,
                           options_, request.seed);
  // Through the flyable positions with no-fly zones, else through the hull cells as the BFS.
  if (request.allowed.size() > 0 || !request.flights.empty()) {
    ws.use_allowed_distances(request.allowed.size() > 0 ? request.allowed : hull.mask(), starts,
                             request.flights);
  }
  ws.link_seam(request.flights);
  // Goal: every region connected and within `tolerance` cells of its desired weight. The tolerance
  // starts at 1 cell (0 when the shares divide exactly); after `limit` iterations it grows by one
  // and the limit halves, up to max_discrepancy. Total iterations ≤ 2 · iteration_limit +
  // max_discrepancy.
  const double slack = 1e-9 * total;  // for sums of non-integer weights
  int tolerance = divides_exactly(out.desired_weight, unit) ? 0 : 1;
  tolerance = std::min(tolerance, options_.max_discrepancy);
  int level_limit = options_.iteration_limit;
  bool capped_by_budget = false;
  if (options_.work_budget > 0) {
    // An iteration evaluates every hull cell for every UAV; the budget bounds DARP's cost on
    // large hulls and fleets, where it does not converge in any affordable number of iterations.
    const double per_iteration = static_cast<double>(n) * hull.cell_count();
    const double affordable = static_cast<double>(options_.work_budget) * 1e6 / per_iteration;
    if (affordable < level_limit) {
      level_limit = std::max(1, static_cast<int>(affordable));
      capped_by_budget = true;
    }
  }
  int iterations = 0;
  bool converged = false;
  bool from_best = false;
  while (!converged) {
    for (int it = 0; it < level_limit; ++it) {
      ++iterations;
      ws.assign();
      ws.check_connectivity();
      const double discrepancy = ws.discrepancy();
      if (ws.all_connected()) {
        if (discrepancy <= tolerance * unit + slack) {
          converged = true;
          break;
        }
        ws.remember_connected(discrepancy);
      }
      if (options_.repair_fallback) ws.remember_balanced(discrepancy + ws.stray_weight());
      ws.update(tolerance * unit);
    }
    if (converged || tolerance >= options_.max_discrepancy) break;
    ++tolerance;
    level_limit = std::max(1, level_limit / 2);
    // The best connected partition seen so far may already meet the relaxed goal.
    if (ws.has_connected() && ws.best_connected_discrepancy() <= tolerance * unit + slack) {
      converged = true;
      from_best = true;
    }
  }

  out.iterations = iterations;
  out.converged = converged;
  using Which = detail::DarpWorkspace::Which;
  if (converged) {
    ws.export_assignment(from_best ? Which::kBestConnected : Which::kCurrent, out.owner,
                         out.region_cells, out.region_weight);
    out.tolerance = tolerance * unit;
    return finish();
  }
  const double connected_before_repair =
      ws.has_connected() ? ws.best_connected_discrepancy() : -1.0;
  if (options_.repair_fallback) ws.repair_best_balanced();
  if (!ws.has_connected()) {
    throw Error(fmt::format(
        "darp: no partition with 4-connected regions found in {} iterations ({} UAVs on hull "
        "'{}'); try other start cells, a larger darp.iteration-limit, or the stripes partitioner",
        iterations, n, hull.source()));
  }
  ws.export_assignment(Which::kBestConnected, out.owner, out.region_cells, out.region_weight);
  out.tolerance = ws.best_connected_discrepancy();
  const bool repaired = connected_before_repair < 0 || out.tolerance < connected_before_repair;
  out.warnings.push_back(fmt::format(
      "darp did not balance the regions within {} in {}{}; returned the best "
      "connected partition found{} (largest imbalance {:g})",
      plural(options_.max_discrepancy, "cell"), plural(iterations, "iteration"),
      capped_by_budget ? " (capped by darp.work-budget)" : "",
      repaired
          ? ", the best-balanced iterate with its stray pieces merged into neighbouring regions"
          : "",
      out.tolerance));
  return finish();
}

}  // namespace hullinspect::partition
