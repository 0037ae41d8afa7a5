#include "support/truth_blindness.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/world/scenario.hpp"

namespace hullinspect::testing {

namespace {

struct Recording final : planners::MissionObserver {
  std::vector<std::vector<sim::Action>> actions;    // per step
  std::vector<std::vector<sim::Reading>> readings;  // per t (all UAVs, in order)
  void record_readings(const sim::Simulator& sim) {
    std::vector<sim::Reading> all;
    for (int k = 0; k < static_cast<int>(sim.uavs().size()); ++k) {
      for (const auto& r : sim.view().sensed.readings(k)) all.push_back(r);
    }
    readings.push_back(std::move(all));
  }
  void on_start(const sim::Simulator& sim, const planners::Planner&) override {
    record_readings(sim);
  }
  void on_step(const sim::Simulator& sim, const planners::Planner&) override {
    actions.emplace_back(sim.applied_actions().begin(), sim.applied_actions().end());
    record_readings(sim);
  }
};

bool same(const std::vector<sim::Reading>& a, const std::vector<sim::Reading>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].index != b[i].index || a[i].value != b[i].value) return false;
  }
  return true;
}

// The time at which each hull cell was first sensed (-1: never).
struct FirstSensed final : planners::MissionObserver {
  std::vector<int> time;
  int t = 0;
  void record(const sim::Simulator& sim) {
    for (int k = 0; k < static_cast<int>(sim.uavs().size()); ++k) {
      for (const auto& r : sim.view().sensed.readings(k)) {
        auto& first = time[static_cast<std::size_t>(r.index)];
        if (first < 0) first = t;
      }
    }
  }
  void on_start(const sim::Simulator& sim, const planners::Planner&) override { record(sim); }
  void on_step(const sim::Simulator& sim, const planners::Planner&) override {
    ++t;
    record(sim);
  }
};

const world::HullMask& checked_hull() {
  return world::default_hull();
}
world::CorrosionParams checked_corrosion() {
  return world::scenario("imperfect").corrosion(checked_hull().width());
}

}  // namespace

std::function<void(grid::Grid<std::int8_t>&)> corrosion_where_sensed_last(
    const std::string& algorithm, const OptionMap& options, const world::MissionParams& params,
    std::uint64_t seed, const world::FailurePlan& failures, int* last_first_sensed, int* altered) {
  const auto& hull = checked_hull();
  const auto corrosion = checked_corrosion();
  const auto a = world::generate_instance(hull, corrosion, seed);
  FirstSensed seen;
  seen.time.assign(static_cast<std::size_t>(hull.mask().size()), -1);
  planners::MissionOptions options_a;
  options_a.observers = {&seen};
  options_a.corrosion = &corrosion;
  options_a.failures = failures;
  auto planner = planners::make_planner(algorithm, options);
  planners::run_mission(hull, a, params, *planner, options_a);
  int last = 0;
  for (int i : hull.cells()) last = std::max(last, seen.time[static_cast<std::size_t>(i)]);
  if (last_first_sensed) *last_first_sensed = last;
  std::vector<int> cells;
  for (int i : hull.cells()) {
    const int t = seen.time[static_cast<std::size_t>(i)];
    if (t >= 0 && 10 * t >= 9 * last && a.truth[i] == 0) cells.push_back(i);
  }
  if (altered) *altered = static_cast<int>(cells.size());
  return [cells](grid::Grid<std::int8_t>& truth) {
    for (int i : cells) truth[i] = 1;
  };
}

::testing::AssertionResult planner_is_truth_blind(
    const std::string& algorithm, const OptionMap& options, const world::MissionParams& params,
    std::uint64_t seed, TruthBlindnessReport* report, const world::FailurePlan& failures,
    const std::function<void(grid::Grid<std::int8_t>&)>& alter_truth) {
  const auto& hull = checked_hull();
  const auto corrosion = checked_corrosion();
  const auto a = world::generate_instance(hull, corrosion, seed);
  world::Instance b = a;
  if (alter_truth) {
    alter_truth(b.truth);
  } else {
    for (int i : hull.cells()) {
      const auto c = hull.mask().cell(i);
      if (c.y >= hull.height() - 6 && (c.x / 3 + c.y / 3) % 4 == 0) b.truth[i] = 1;
    }
  }
  Recording ra;
  Recording rb;
  auto pa = planners::make_planner(algorithm, options);
  auto pb = planners::make_planner(algorithm, options);
  // Both instances come from the same scenario: a planner may know its statistics (p_TP, p_FP),
  // which are the same for both.
  planners::MissionOptions oa;
  oa.observers = {&ra};
  oa.corrosion = &corrosion;
  oa.failures = failures;
  planners::MissionOptions ob;
  ob.observers = {&rb};
  ob.corrosion = &corrosion;
  ob.failures = failures;
  planners::run_mission(hull, a, params, *pa, oa);
  planners::run_mission(hull, b, params, *pb, ob);

  // Decision t is made from readings 0..t, so decisions before the first differing reading must
  // match.
  std::size_t t = 0;
  while (t < ra.readings.size() && t < rb.readings.size() && same(ra.readings[t], rb.readings[t]))
    ++t;
  const std::size_t first_diff = t;
  if (report) {
    report->first_differing_reading = first_diff < std::min(ra.readings.size(), rb.readings.size())
                                          ? static_cast<int>(first_diff)
                                          : -1;
    report->steps_compared = static_cast<int>(std::min(first_diff, ra.actions.size()));
  }
  for (std::size_t s = 0; s < first_diff && s < ra.actions.size() && s < rb.actions.size(); ++s) {
    if (ra.actions[s] != rb.actions[s]) {
      return ::testing::AssertionFailure() << fmt::format(
                 "{}: decision at t = {} differs although readings were identical up to t = {}",
                 algorithm, s, first_diff);
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace hullinspect::testing
