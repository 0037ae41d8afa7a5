#pragma once
// Shared invariant checker for whole missions: attach it as a MissionObserver, then assert ok().

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hullinspect/planners/mission.hpp"

namespace hullinspect::testing {

/// Checks after every step: each UAV followed the model's motion rules (sim/uav_rules.hpp, the
/// rules the trace reader applies too), stayed on the grid and off every no-fly position; M only moved forward (0 → 1/2/3, 2 → 1/3, 1 and 3 final,
/// −1 fixed); the simulator's changed-cell list is exactly the set of cells that changed; c and m
/// never decrease; the simulator's counters agree with a rescan of M. With a separation D > 0: no
/// two UAVs closer than D (max(|Δx|, |Δy|)) at any t, none exchanging cells, and the simulator's
/// separation_conflicts and min_separation agree with this count.
class MissionChecker final : public planners::MissionObserver {
 public:
  void on_start(const sim::Simulator& sim, const planners::Planner& planner) override;
  void on_step(const sim::Simulator& sim, const planners::Planner& planner) override;
  ::testing::AssertionResult ok() const;
  int steps_checked() const { return steps_; }

 private:
  void fail(const std::string& what);
  grid::Grid<std::int8_t> last_map_;
  std::vector<sim::UavState> last_uavs_;
  double last_c_ = 0;
  double last_m_ = 0;
  void check_separation(const sim::Simulator& sim);
  int steps_ = 0;
  long long conflicts_ = 0;
  int min_separation_ = -1;
  std::vector<std::string> failures_;
};

}  // namespace hullinspect::testing
