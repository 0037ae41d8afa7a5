#include "support/mission_checker.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "hullinspect/sim/uav_rules.hpp"

namespace hullinspect::testing {

void MissionChecker::fail(const std::string& what) {
  if (failures_.size() < 10) failures_.push_back(what);
}

void MissionChecker::on_start(const sim::Simulator& sim, const planners::Planner&) {
  last_map_ = sim.map();
  last_uavs_.assign(sim.uavs().begin(), sim.uavs().end());
  last_c_ = sim.c_percent();
  last_m_ = sim.m_percent();
  const auto& sites = sim.launch_legs().sites;
  check_separation(sim);
  for (const auto& u : sim.uavs()) {
    // With launch sites every UAV starts on the ground at one; otherwise on a hull cell.
    if (!sites.empty()) {
      if (std::find(sites.begin(), sites.end(), u.pos) == sites.end() || u.away_left == 0)
        fail(fmt::format("UAV starts at ({}, {}), not on the ground at a launch site", u.pos.x,
                         u.pos.y));
    } else if (!sim.hull().is_hull(u.pos)) {
      fail(fmt::format("UAV starts off the hull at ({}, {})", u.pos.x, u.pos.y));
    }
    if (sim.no_fly(u.pos))
      fail(fmt::format("UAV starts on the no-fly position ({}, {})", u.pos.x, u.pos.y));
  }
}

// Pairwise, from the UAV states alone (the rule of docs/model.md, "Separation": airborne UAVs
// only), independently of the simulator's own count, which must agree.
void MissionChecker::check_separation(const sim::Simulator& sim) {
  const int d = sim.params().separation;
  if (d <= 0) return;
  const auto uavs = sim.uavs();
  for (std::size_t a = 0; a < uavs.size(); ++a) {
    if (!uavs[a].airborne) continue;
    for (std::size_t b = a + 1; b < uavs.size(); ++b) {
      if (!uavs[b].airborne) continue;
      const grid::Cell pa = uavs[a].pos;
      const grid::Cell pb = uavs[b].pos;
      const bool exchanged = pa != pb && pa == last_uavs_[b].pos && pb == last_uavs_[a].pos;
      const int gap = exchanged ? 0 : std::max(std::abs(pa.x - pb.x), std::abs(pa.y - pb.y));
      if (min_separation_ < 0 || gap < min_separation_) min_separation_ = gap;
      if (gap >= d) continue;
      ++conflicts_;
      fail(fmt::format("t={} UAVs {} ({}, {}) and {} ({}, {}) {} (separation {})", sim.time(), a,
                       pa.x, pa.y, b, pb.x, pb.y,
                       exchanged ? "exchanged cells" : fmt::format("are {} apart", gap), d));
    }
  }
  if (sim.separation_conflicts() != conflicts_) {
    fail(fmt::format("t={} the simulator counts {} separation conflicts, the checker {}",
                     sim.time(), sim.separation_conflicts(), conflicts_));
  }
  if (sim.min_separation().value_or(-1) != min_separation_) {
    fail(fmt::format("t={} the simulator's min_separation {} is not the checker's {}", sim.time(),
                     sim.min_separation().value_or(-1), min_separation_));
  }
}

namespace {
bool forward(std::int8_t before, std::int8_t after) {
  if (before == after) return true;
  switch (before) {
    case sim::kUnknown:
      return after == sim::kClean || after == sim::kCorrosionSeen || after == sim::kInspected;
    case sim::kCorrosionSeen:
      return after == sim::kClean || after == sim::kInspected;
    default:
      return false;
  }
}
}  // namespace

void MissionChecker::on_step(const sim::Simulator& sim, const planners::Planner&) {
  ++steps_;
  const int t = sim.time();
  const auto uavs = sim.uavs();
  for (std::size_t k = 0; k < uavs.size(); ++k) {
    const auto& before = last_uavs_[k];
    const auto& after = uavs[k];
    if (auto broken =
            sim::step_violation(before, after, sim.plane_change_steps(), sim.flight_steps())) {
      fail(fmt::format("t={} UAV {} {}", t, k, *broken));
    }
    if (auto broken = sim::state_violation(after, sim.plane_change_steps())) {
      fail(fmt::format("t={} UAV {} {}", t, k, *broken));
    }
    if (!sim.map().contains(after.pos)) fail(fmt::format("t={} UAV {} off the grid", t, k));
    if (sim.map().contains(after.pos) && sim.no_fly(after.pos)) {
      fail(fmt::format("t={} UAV {} on the no-fly position ({}, {})", t, k, after.pos.x,
                       after.pos.y));
    }
  }
  const auto& map = sim.map();
  std::set<int> changed(sim.changed_cells().begin(), sim.changed_cells().end());
  int known = 0;
  for (int i = 0; i < map.size(); ++i) {
    if (!forward(last_map_[i], map[i])) {
      fail(fmt::format("t={} cell ({}, {}) went back from M={} to M={}", t, map.cell(i).x,
                       map.cell(i).y, last_map_[i], map[i]));
    }
    if ((last_map_[i] != map[i]) != (changed.count(i) == 1)) {
      fail(
          fmt::format("t={} changed-cell list wrong at ({}, {})", t, map.cell(i).x, map.cell(i).y));
    }
    if (map[i] == sim::kClean || map[i] == sim::kInspected) ++known;
  }
  if (known != sim.known_cells())
    fail(fmt::format("t={} known cells {} but rescan finds {}", t, sim.known_cells(), known));
  if (sim.c_percent() < last_c_) fail(fmt::format("t={} c decreased", t));
  if (sim.m_percent() < last_m_) fail(fmt::format("t={} m decreased", t));
  last_c_ = sim.c_percent();
  last_m_ = sim.m_percent();
  last_map_ = map;
  check_separation(sim);
  last_uavs_.assign(uavs.begin(), uavs.end());
}

::testing::AssertionResult MissionChecker::ok() const {
  if (failures_.empty()) return ::testing::AssertionSuccess() << steps_ << " steps checked";
  auto r = ::testing::AssertionFailure();
  for (const auto& f : failures_) r << f << "\n";
  return r;
}

}  // namespace hullinspect::testing
