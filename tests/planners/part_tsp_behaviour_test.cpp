// Behaviour of Part-TSP / Part-TSP₀ on small hand-made instances (model.md §5.3).

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "hullinspect/io/result_json.hpp"
#include "hullinspect/io/trace_recorder.hpp"
#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/part_tsp_planner.hpp"
#include "hullinspect/world/scenario.hpp"
#include "part_tsp_recorder.hpp"
#include "part_tsp_test_support.hpp"
#include "support/mission_checker.hpp"

namespace hullinspect::testing {
namespace {

using planners::PartTspOptions;

/// Rows (top first) of an a × b all-hull matrix with '1' where `corroded(x, y)`.
std::vector<std::string> rows(int a, int b, const std::function<bool(int, int)>& corroded) {
  std::vector<std::string> out;
  for (int y = b - 1; y >= 0; --y) {
    std::string row;
    for (int x = 0; x < a; ++x) row += corroded(x, y) ? '1' : '0';
    out.push_back(row);
  }
  return out;
}

bool in_box(int x, int y, int x0, int x1, int y0, int y1) {
  return x >= x0 && x <= x1 && y >= y0 && y <= y1;
}

/// Always hands out the same partition (a hand-made assignment matrix A).
class FixedPartitionSource final : public planners::PartitionSource {
 public:
  explicit FixedPartitionSource(grid::Grid<std::int16_t> owner) {
    partition_.owner = std::move(owner);
    for (int i = 0; i < partition_.owner.size(); ++i) {
      const int k = partition_.owner[i];
      if (k < 0) continue;
      if (static_cast<int>(partition_.region_cells.size()) <= k) {
        partition_.region_cells.resize(static_cast<std::size_t>(k) + 1);
      }
      ++partition_.region_cells[static_cast<std::size_t>(k)];
    }
  }
  std::shared_ptr<const partition::Partition> get(std::string_view, const OptionMap&,
                                                  const partition::PartitionRequest&) override {
    return std::make_shared<const partition::Partition>(partition_);
  }

 private:
  partition::Partition partition_;
};

struct Run {
  MissionRecorder recorder;
  sim::MissionResult result;
  sim::PlannerStats stats;
  grid::Grid<std::int16_t> owner;  ///< the partition the planner used
};

/// Runs one mission with the recorder and the shared checker attached; fails the test if the
/// mission does not complete or breaks an invariant.
std::unique_ptr<Run> run(const HandInstance& h, const world::MissionParams& params,
                         PartTspOptions o, planners::PartitionSource* partitions = nullptr) {
  auto out = std::make_unique<Run>();
  o.partitioner = "stripes";
  auto planner = make_part_tsp(o);
  MissionChecker checker;
  planners::MissionOptions mo;
  mo.observers = {&checker, &out->recorder};
  mo.partitions = partitions;
  out->result = planners::run_mission(h.hull, h.instance, params, *planner, mo);
  out->stats = planner->stats();
  out->owner = planner->partition()->owner;
  EXPECT_TRUE(out->result.complete);
  EXPECT_TRUE(checker.ok());
  return out;
}

world::MissionParams small_params(std::vector<grid::Cell> starts) {
  world::MissionParams p;
  p.uavs = static_cast<int>(starts.size());
  p.s1 = 3;
  p.s2 = 5;  // u_z = 1
  p.starts = std::move(starts);
  p.time_limit = 5000;
  return p;
}

// 30 × 10, two clusters far from the start (2, 5): nothing corroded is in view during the first
// steps, so t_d counts from the mission start.
bool two_clusters(int x, int y) {
  return in_box(x, y, 20, 22, 1, 2) || in_box(x, y, 12, 13, 8, 8);
}

int first_plane_change(const MissionRecorder& r, int k, int from = 0) {
  for (int t = from; t <= r.last_time(); ++t) {
    if (r.action(k, t) == sim::Action::kChangePlane) return t;
  }
  return -1;
}

TEST(PartTspBehaviour, WithAPerfectPriorTheUavDescendsAfterR1Steps) {
  const auto truth = rows(30, 10, two_clusters);
  const auto h = hand_instance(truth, truth);
  for (int r1 : {0, 2, 4}) {
    PartTspOptions o;
    o.r1 = r1;
    const auto r = run(h, small_params({{2, 5}}), o);
    EXPECT_EQ(first_plane_change(r->recorder, 0), r1) << "r1 = " << r1;
    for (int t = 0; t < r1; ++t) EXPECT_EQ(r->recorder.mode(0, t), "cover-z2") << t;
    EXPECT_EQ(r->recorder.mode(0, r1), "descending");
  }
}

TEST(PartTspBehaviour, InspectsEveryExpectedCellOfItsRegionBeforeCoveringTheRest) {
  // Two UAVs, stripes partition: UAV 0 gets the left half, UAV 1 the right half.
  const auto truth = rows(60, 10, [](int x, int y) {
    return in_box(x, y, 5, 7, 1, 2) || in_box(x, y, 22, 24, 7, 8) || in_box(x, y, 40, 41, 0, 4) ||
           in_box(x, y, 55, 58, 8, 9);
  });
  const auto h = hand_instance(truth, truth);
  const auto r = run(h, small_params({{10, 5}, {45, 5}}), PartTspOptions{});
  for (int k = 0; k < 2; ++k) {
    const int descent = first_plane_change(r->recorder, k);
    ASSERT_GE(descent, 0);
    const int ascent = first_plane_change(r->recorder, k, descent + 1);
    ASSERT_GT(ascent, descent) << "UAV " << k;
    // Between the two, the UAV only inspects.
    for (int t = descent + 2; t < ascent; ++t) EXPECT_EQ(r->recorder.mode(k, t), "inspect-z1") << t;
    // At the ascent every expected corroded cell of its region is inspected, while most of its
    // region is still unknown.
    const auto& map = r->recorder.frames[static_cast<std::size_t>(ascent)].map;
    int unknown = 0;
    int expected = 0;
    for (int i = 0; i < map.size(); ++i) {
      if (r->owner[i] != k) continue;
      if (h.instance.prior[i] == 1) {
        ++expected;
        EXPECT_EQ(map[i], sim::kInspected) << map.cell(i).x << "," << map.cell(i).y;
      }
      if (map[i] == sim::kUnknown) ++unknown;
    }
    EXPECT_GE(expected, 6) << "UAV " << k;
    EXPECT_GT(unknown, 100) << "UAV " << k;
    // With a perfect prior nothing new turns up: one descent and one ascent.
    EXPECT_EQ(r->result.uavs[static_cast<std::size_t>(k)].plane_changes, 2);
  }
  EXPECT_EQ(r->result.t_c, std::min(r->result.t_c, r->result.t_m));
}

TEST(PartTspBehaviour, PartTsp0IgnoresThePrior) {
  const auto truth = rows(30, 10, two_clusters);
  const auto empty = rows(30, 10, [](int, int) { return false; });
  const auto with_prior = hand_instance(truth, truth);
  const auto without_prior = hand_instance(truth, empty);
  PartTspOptions o;
  o.use_prior = false;
  const auto a = run(with_prior, small_params({{2, 5}}), o);
  const auto b = run(without_prior, small_params({{2, 5}}), o);
  ASSERT_EQ(a->recorder.frames.size(), b->recorder.frames.size());
  for (int t = 0; t <= a->recorder.last_time(); ++t) {
    ASSERT_EQ(a->recorder.action(0, t), b->recorder.action(0, t)) << "t = " << t;
  }
  EXPECT_EQ(a->result.t_c, b->result.t_c);
  // Part-TSP does use it (else the comparison above proves nothing).
  o.use_prior = true;
  const auto c = run(with_prior, small_params({{2, 5}}), o);
  const auto d = run(without_prior, small_params({{2, 5}}), o);
  EXPECT_NE(c->result.t_c, d->result.t_c);
}

TEST(PartTspBehaviour, SameInputsGiveIdenticalResultsAndTraces) {
  for (const char* name : {"part-tsp", "part-tsp0"}) {
    planners::MissionSpec spec;
    spec.algorithm = name;
    spec.params.uavs = 3;
    spec.corrosion = world::scenario("imperfect").corrosion(230);
    spec.seed = 11;
    auto run_traced = [&] {
      const auto instance =
          world::generate_instance(world::default_hull(), spec.corrosion, spec.seed);
      auto planner = planners::make_planner(spec.algorithm, spec.planner_options);
      io::TraceRecorder recorder(instance, io::spec_json(spec, "builtin:default"));
      planners::MissionOptions options;
      options.observers = {&recorder};
      const auto r =
          planners::run_mission(world::default_hull(), instance, spec.params, *planner, options);
      auto summary = io::result_json(spec, r);
      for (const char* timing : {"planner_seconds", "tsp_seconds", "tsp_max_seconds"}) {
        summary.erase(timing);
      }
      return std::pair{summary, recorder.finish(r)};
    };
    const auto [a, trace_a] = run_traced();
    const auto [b, trace_b] = run_traced();
    EXPECT_EQ(a, b) << name;
    EXPECT_EQ(trace_a, trace_b) << name;
    EXPECT_GT(a["tsp_solves"].get<int>(), 0) << name;
    EXPECT_GT(a["replans"].get<int>(), 0) << name;
  }
}

TEST(PartTspBehaviour, R2AvoidsPlaneOscillationOnALargeCluster) {
  // Part-TSP₀ (no prior) meets one 13 × 9 cluster: with r2 = 0 it climbs back as soon as what it
  // detected is inspected, sees more of the cluster and descends again; r2 = 1 keeps it down while
  // it keeps finding corrosion.
  const auto truth = rows(40, 15, [](int x, int y) { return in_box(x, y, 14, 26, 3, 11); });
  const auto empty = rows(40, 15, [](int, int) { return false; });
  const auto h = hand_instance(truth, empty);
  world::MissionParams params = small_params({{2, 7}});
  params.s1 = 5;
  params.s2 = 7;
  PartTspOptions o;
  o.use_prior = false;
  o.r2 = 0;
  const auto eager = run(h, params, o);
  o.r2 = 1;
  const auto patient = run(h, params, o);
  const int eager_changes = eager->result.uavs[0].plane_changes;
  const int patient_changes = patient->result.uavs[0].plane_changes;
  EXPECT_GT(eager_changes, patient_changes);
  EXPECT_LE(patient_changes, 4);
  RecordProperty("plane_changes_r2_0", eager_changes);
  RecordProperty("plane_changes_r2_1", patient_changes);
}

TEST(PartTspBehaviour, CoversOnlyItsRegionButMayCrossAnotherInTransit) {
  // UAV 1 owns the block x 8–11, y 0–6; UAV 0 owns the rest, a U around it. UAV 0's corrosion
  // lies across the block from its start, so its x-first transit crosses region 1.
  grid::Grid<std::int16_t> owner(20, 10, 0);
  for (int y = 0; y <= 6; ++y)
    for (int x = 8; x <= 11; ++x) owner(x, y) = 1;
  FixedPartitionSource partitions(owner);
  const auto truth = rows(20, 10, [](int x, int y) { return in_box(x, y, 15, 16, 2, 2); });
  const auto h = hand_instance(truth, truth);
  const auto r = run(h, small_params({{2, 2}, {9, 3}}), PartTspOptions{}, &partitions);
  bool crossed = false;
  for (const auto& f : r->recorder.frames) crossed = crossed || owner[f.uavs[0].pos] == 1;
  EXPECT_TRUE(crossed);
  // Its plans (waypoints) only ever lie over columns that hold cells of its own region.
  for (const auto& f : r->recorder.frames) {
    if (f.plans.empty()) continue;
    for (const auto& c : f.plans[0]) {
      bool column_has_region0 = false;
      for (int y = 0; y < 10; ++y) column_has_region0 = column_has_region0 || owner(c.x, y) == 0;
      EXPECT_TRUE(column_has_region0) << c.x;
    }
  }
}

TEST(PartTspBehaviour, TraceShowsTheFsmStatesAndPlans) {
  const auto truth = rows(30, 10, two_clusters);
  const auto h = hand_instance(truth, truth);
  const auto r = run(h, small_params({{2, 5}}), PartTspOptions{});
  std::vector<std::string> modes;
  for (int t = 0; t <= r->recorder.last_time(); ++t) {
    const auto& m = r->recorder.mode(0, t);
    if (modes.empty() || modes.back() != m) modes.push_back(m);
    const auto& f = r->recorder.frames[static_cast<std::size_t>(t + 1)];
    if (m == "cover-z2" || m == "inspect-z1") {
      ASSERT_FALSE(f.plans[0].empty()) << t;
      EXPECT_EQ(f.targets[0], f.plans[0].front()) << t;
    }
  }
  EXPECT_EQ(modes, (std::vector<std::string>{"cover-z2", "descending", "inspect-z1", "ascending",
                                             "cover-z2"}));
  EXPECT_GE(r->stats.tsp_solves, 1);  // the two clusters lie in two strips at z = 1
  EXPECT_GE(r->stats.replans, 2);
  EXPECT_GE(r->stats.tsp_seconds, r->stats.tsp_max_seconds);
  EXPECT_GT(r->stats.tsp_max_seconds, 0.0);
}

TEST(PartTspBehaviour, UavsThatStartAtTheCloseUpPlaneComplete) {
  const auto truth = rows(30, 10, two_clusters);
  const auto h = hand_instance(truth, truth);
  auto params = small_params({{2, 5}, {25, 5}});
  params.start_z = 1;
  for (bool use_prior : {true, false}) {
    PartTspOptions o;
    o.use_prior = use_prior;
    const auto r = run(h, params, o);
    EXPECT_TRUE(r->result.complete);
  }
}

}  // namespace
}  // namespace hullinspect::testing
