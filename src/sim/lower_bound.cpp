#include "hullinspect/sim/lower_bound.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>

#include "hullinspect/grid/distance.hpp"
#include "hullinspect/world/battery.hpp"
#include "hullinspect/world/launch_sites.hpp"
#include "hullinspect/world/no_fly.hpp"
#include "hullinspect/world/standoff_surface.hpp"

namespace hullinspect::sim {

namespace {

long long ceil_div(long long a, long long b) {
  return a <= 0 ? 0 : (a + b - 1) / b;
}

/// Fewest steps from `s` to a position whose footprint of half-width h holds `c`; on a grid
/// `wrap` columns wide that closes on itself (0: it does not) the columns' gap is the shorter way
/// round, across the seam (each flight is at least one step).
int reach(grid::Cell s, grid::Cell c, int h, int wrap) {
  int dx = std::abs(s.x - c.x);
  if (wrap > 0) dx = std::min(dx, wrap - dx);
  return std::max(0, dx - h) + std::max(0, std::abs(s.y - c.y) - h);
}

/// Transit steps of the fleet for D arrivals at z = 1 in total: a UAV that starts at z = 2 pays u_z
/// per descent and u_z per ascent between two of its descents, so the fleet pays at least
/// u_z·max(D, 2·D − n). A UAV starting at z = 1 has its first arrival free and pays 2·u_z for each
/// further one.
long long transit_steps(long long d, int n, int uz, int start_z) {
  if (start_z == 1) return d <= n ? 0 : 2LL * uz * (d - n);
  return static_cast<long long>(uz) * std::max(d, 2 * d - n);
}

}  // namespace

LowerBound lower_bound(const world::HullMask& hull, const grid::Grid<std::int8_t>& truth,
                       const world::MissionParams& params) {
  return lower_bound(hull, truth, params, world::start_cells(params, hull));
}

LowerBound lower_bound(const world::HullMask& hull, const grid::Grid<std::int8_t>& truth,
                       const world::MissionParams& params, std::span<const grid::Cell> starts) {
  const int n = params.uavs;
  const int s1 = params.s1;
  const int s2 = params.s2;
  const int uz = params.plane_change_steps();
  const int h1 = params.half_side(1);
  const int h2 = params.half_side(2);

  // With launch sites a UAV reaches its start cell only after its outbound leg, and the last
  // landing comes at least a descent and a transfer after the hull is complete.
  std::vector<int> outbound(starts.size(), 0);
  long long outbound_total = 0;
  int landing = 0;
  // With a battery, every sortie flies out from a site and back (at least the ground legs and
  // the flight between the site and the nearest hull cell each way): what it leaves for work.
  const world::BatterySteps battery = world::battery_steps(params);
  long long sortie_legs = 0;
  if (!params.launch_sites.empty()) {
    const auto reach_map = world::compute_reachability(hull, params.no_fly.get(), s1, s2, starts);
    const auto legs = world::plan_launch_legs(params, hull, reach_map, starts);
    outbound = legs.outbound;
    for (const int o : outbound) outbound_total += o;
    landing = legs.takeoff_steps + legs.transfer_steps;
    int nearest = std::numeric_limits<int>::max();
    for (const auto& d : legs.flight_home) {
      for (int i : hull.cells()) nearest = std::min(nearest, d[i]);
    }
    sortie_legs = 2LL * (landing + std::min(nearest, grid::kUnreachable));
  }
  // Fleet steps that endurance adds to a work of `work` steps: the fleet flies at least
  // ceil(work / (E − legs)) sorties; each one after a UAV's first pays its legs and a swap.
  const auto sortie_cost = [&](long long work) -> long long {
    if (!battery.limited || params.launch_sites.empty()) return 0;
    const long long useful = battery.endurance - sortie_legs;
    if (useful <= 0) return 0;
    const long long sorties = ceil_div(work, useful);
    return std::max(0LL, sorties - n) * (sortie_legs + battery.swap);
  };

  long long hull_cells = 0;
  long long corroded = 0;
  int reach_c = 0;
  int reach_m = 0;
  const int wrap = world::seam_links(hull).seam.empty() ? 0 : hull.width();
  for (int i : hull.cells()) {
    ++hull_cells;
    const grid::Cell c = hull.mask().cell(i);
    const bool corr = truth[i] == 1;
    if (corr) ++corroded;
    int best = std::numeric_limits<int>::max();
    for (std::size_t k = 0; k < starts.size(); ++k) {
      const grid::Cell s = starts[k];
      // A clean cell is known once seen from either plane; a corroded one only from z = 1, which
      // a UAV starting at z = 2 reaches after u_z steps of transit.
      const int d = outbound[k] + (corr ? reach(s, c, h1, wrap) + (params.start_z == 2 ? uz : 0)
                                        : reach(s, c, h2, wrap));
      best = std::min(best, d);
    }
    if (corr) reach_c = std::max(reach_c, best);
    reach_m = std::max(reach_m, best);
  }

  // Rate: the fleet's step budget n·T must pay for A moves at z = 2, C moves at z = 1 and the
  // transit of D descents. Observation: every observed cell lies in the z = 2 square around some
  // position a UAV visited (the z = 1 footprint is inside it), and a walk of M moves grows that
  // union by at most s2 cells per move, so s2·(A + C) >= hull cells − n·s2². Inspection: every
  // corroded cell lies in some z = 1 footprint, new ones only on arrival at z = 1 (s1² each) or by
  // a z = 1 move (s1 each), so s1²·D + s1·C >= corroded cells. Minimised over D.
  const long long unseen = std::max(0LL, hull_cells - static_cast<long long>(n) * s2 * s2);
  const long long s1sq = static_cast<long long>(s1) * s1;
  long long best_m = std::numeric_limits<long long>::max();
  long long best_c = std::numeric_limits<long long>::max();
  const long long d_min = (corroded > 0 && params.start_z == 2) ? 1 : 0;
  const long long d_max = std::max(d_min, ceil_div(corroded, s1sq));
  for (long long d = d_min; d <= d_max; ++d) {
    const long long c_moves = ceil_div(corroded - s1sq * d, s1);
    const long long a_moves = ceil_div(unseen - static_cast<long long>(s2) * c_moves, s2);
    const long long transit = transit_steps(d, n, uz, params.start_z);
    best_m = std::min(best_m, a_moves + c_moves + transit);
    best_c = std::min(best_c, c_moves + transit);
  }

  LowerBound b;
  b.sortie_t_m = static_cast<int>(ceil_div(sortie_cost(best_m), n));
  b.rate_t_m =
      static_cast<int>(ceil_div(best_m + outbound_total + sortie_cost(best_m), n)) + landing;
  b.rate_t_c = corroded == 0
                   ? 0
                   : static_cast<int>(ceil_div(best_c + outbound_total + sortie_cost(best_c), n));
  b.reach_t_m = reach_m + landing;
  b.reach_t_c = corroded == 0 ? 0 : reach_c;
  b.t_c = std::max(b.rate_t_c, b.reach_t_c);
  b.t_m = std::max({b.rate_t_m, b.reach_t_m, b.t_c + landing});
  return b;
}

}  // namespace hullinspect::sim
