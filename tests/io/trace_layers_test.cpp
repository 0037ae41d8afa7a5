// Planner layers in a trace (docs/trace-format.md, version 2): written as changes with a whole set
// at least every kLayerKeyframeInterval frames, they rebuild exactly the sets the planner reported
// at every frame, and they cost far fewer bytes than whole sets every frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "hullinspect/io/trace_reader.hpp"
#include "hullinspect/io/trace_recorder.hpp"
#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/instance.hpp"

namespace hullinspect::io {
namespace {

using nlohmann::json;
using LayerSets = std::map<std::string, std::vector<int>>;

// Records, at every frame, every layer's whole set as the planner reports it.
class LayerLog final : public planners::MissionObserver, private planners::AnnotationSink {
 public:
  void on_start(const sim::Simulator&, const planners::Planner& planner) override { log(planner); }
  void on_step(const sim::Simulator&, const planners::Planner& planner) override { log(planner); }
  std::vector<LayerSets> frames;

 private:
  void log(const planners::Planner& planner) {
    frames.emplace_back(frames.empty() ? LayerSets{} : frames.back());
    planner.annotate(*this);
  }
  void uav(int, std::string_view, grid::Cell, std::span<const grid::Cell>) override {}
  void cells(std::string_view layer, std::span<const int> indices) override {
    std::vector<int> sorted(indices.begin(), indices.end());
    std::sort(sorted.begin(), sorted.end());
    frames.back()[std::string(layer)] = std::move(sorted);
  }
};

struct Recorded {
  json trace;
  std::vector<LayerSets> expected;
};

const Recorded& coop_frontier_mission() {
  static const Recorded recorded = [] {
    const auto& hull = world::default_hull();
    world::MissionParams params;
    params.uavs = 6;
    const auto instance = world::generate_instance(
        hull, world::CorrosionParams::homogeneous(hull.width(), 0.005, 5), 3);
    auto planner = planners::make_planner("coop-frontier");
    TraceRecorder recorder(instance, json{{"algorithm", "coop-frontier"}});
    LayerLog log;
    planners::MissionOptions options;
    options.observers = {&recorder, &log};
    const auto result = planners::run_mission(hull, instance, params, *planner, options);
    return Recorded{recorder.finish(result), log.frames};
  }();
  return recorded;
}

TEST(TraceLayers, ChangesRebuildTheReportedSetsAtEveryFrame) {
  const auto& [trace, expected] = coop_frontier_mission();
  EXPECT_NO_THROW(validate_trace(trace, "coop.json"));
  const auto& frames = trace["frames"];
  ASSERT_EQ(frames.size(), expected.size());
  std::map<std::string, std::set<int>> current;
  std::map<std::string, int> last_full;
  int deltas = 0;
  for (std::size_t t = 0; t < frames.size(); ++t) {
    if (auto l = frames[t].find("l"); l != frames[t].end()) {
      for (const auto& [name, value] : l->items()) {
        auto& set = current[name];
        if (value.is_array()) {
          set = value.get<std::set<int>>();
          last_full[name] = static_cast<int>(t);
          continue;
        }
        ++deltas;
        ASSERT_TRUE(last_full.contains(name)) << "frame " << t;
        EXPECT_LT(static_cast<int>(t) - last_full[name], kLayerKeyframeInterval) << "frame " << t;
        for (int c : value["add"])
          EXPECT_TRUE(set.insert(c).second) << "frame " << t << " adds " << c;
        for (int c : value["remove"])
          EXPECT_EQ(set.erase(c), 1u) << "frame " << t << " removes " << c;
      }
    }
    for (const auto& [name, cells] : expected[t]) {
      ASSERT_EQ(std::vector<int>(current[name].begin(), current[name].end()), cells)
          << "layer " << name << " at frame " << t;
    }
  }
  EXPECT_GT(deltas, 100) << "the mission should exercise layer changes";
}

TEST(TraceLayers, ChangesCostAFractionOfWholeSets) {
  const auto& [trace, expected] = coop_frontier_mission();
  std::size_t written = 0;
  for (const auto& f : trace["frames"]) {
    if (auto l = f.find("l"); l != f.end()) written += l->dump().size();
  }
  // What version 1 wrote: the whole set of every layer at every frame where it changed.
  std::size_t whole = 0;
  for (std::size_t t = 0; t < expected.size(); ++t) {
    for (const auto& [name, cells] : expected[t]) {
      if (t > 0 && expected[t - 1].contains(name) && expected[t - 1].at(name) == cells) continue;
      whole += json(cells).dump().size() + name.size() + 4;
    }
  }
  EXPECT_LT(written * 5, whole) << written << " bytes of layers against " << whole;
}

}  // namespace
}  // namespace hullinspect::io
