// Sweep-Inspect plans its own battery returns in whole missions (docs/sweep-inspect.md, "Planned
// returns"): with planned-returns it sends UAVs home itself, none crashes and every sortie ends
// with the reserve; without it, it sends none and the sortie layer alone does.

#include <gtest/gtest.h>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/mission_checker.hpp"

namespace hullinspect::planners {
namespace {

// Sweep-Inspect, counting the UAVs it sends home itself.
class CountingReturns final : public Planner {
 public:
  explicit CountingReturns(bool planned)
      : inner_(make_planner("sweep-inspect", {{"planned-returns", planned ? "true" : "false"}})) {}
  void start(const PlannerContext& context) override { inner_->start(context); }
  void decide(const sim::PlannerView& view, std::span<sim::Action> actions) override {
    inner_->decide(view, actions);
  }
  void returns(const sim::PlannerView& view, std::vector<int>& uavs) override {
    const std::size_t before = uavs.size();
    inner_->returns(view, uavs);
    sent_home += static_cast<int>(uavs.size() - before);
  }
  bool idle(const sim::PlannerView& view) const override { return inner_->idle(view); }
  int sent_home = 0;

 private:
  std::unique_ptr<Planner> inner_;
};

sim::MissionResult fly(CountingReturns& planner) {
  const auto& hull = world::default_hull();
  MissionSpec spec;
  spec.seed = 3;
  spec.params.uavs = 4;
  spec.params.launch_sites = {{hull.width() / 2, 0}};
  spec.params.endurance_s = 400;
  spec.params.swap_time_s = 60;
  spec.corrosion = world::scenario("imperfect").corrosion(hull.width());
  testing::MissionChecker checker;
  MissionOptions options;
  options.observers = {&checker};
  options.corrosion = prior_statistics(spec);
  const auto r = run_mission(hull, mission_instance(spec, hull), spec.params, planner, options);
  EXPECT_TRUE(checker.ok());
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(r.battery_crashes, 0);
  return r;
}

TEST(SweepReturnsMission, PlansItsOwnReturnsWithoutACrash) {
  CountingReturns planned(true);
  const auto r = fly(planned);
  EXPECT_GT(planned.sent_home, 0);
  int swaps = 0;
  for (const auto& u : r.uavs) {
    swaps += u.swaps;
    EXPECT_GE(u.min_battery, 40);  // the reserve, 10 % of 400 s
  }
  EXPECT_LE(planned.sent_home, swaps);
}

TEST(SweepReturnsMission, WithoutPlannedReturnsTheLayerAloneSendsUavsHome) {
  CountingReturns layer_only(false);
  const auto r = fly(layer_only);
  EXPECT_EQ(layer_only.sent_home, 0);
  int swaps = 0;
  for (const auto& u : r.uavs) swaps += u.swaps;
  EXPECT_GT(swaps, 0);  // the layer sent them home
}

}  // namespace
}  // namespace hullinspect::planners
