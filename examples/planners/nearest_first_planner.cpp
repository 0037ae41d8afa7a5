// A user planner outside src/ (tutorial 04, docs/user-planners.md): "nearest-first" descends to the
// close-up plane and sends each UAV to the nearest cell still unknown or uninspected (M = 0 or 2),
// keeping the fleet's targets `separation` cells apart. It is compiled into the CLI, the tests and
// the Python module (examples/CMakeLists.txt) and registered by the one line at the bottom, so
// `hullinspect run -a nearest-first`, configs, experiments, `hullinspect list` and
// hullinspect.run_mission(algorithm="nearest-first") all find it.
//
// For brevity it scans the map for targets every step; the built-in planners keep incremental
// sets instead (docs/architecture.md, "Conventions").

#include <cstdlib>
#include <limits>
#include <memory>
#include <vector>

#include "hullinspect/planners/planner.hpp"

namespace {

using namespace hullinspect;

struct NearestFirstOptions {
  int separation = 3;  ///< smallest Manhattan distance between two UAVs' targets
};

class NearestFirstPlanner final : public planners::Planner {
 public:
  explicit NearestFirstPlanner(NearestFirstOptions options) : options_(options) {}

  void start(const planners::PlannerContext& context) override {
    targets_.assign(static_cast<std::size_t>(context.params.uavs), grid::Cell{-1, -1});
  }

  void decide(const sim::PlannerView& view, std::span<sim::Action> actions) override {
    for (std::size_t k = 0; k < actions.size(); ++k) {
      const sim::UavState& uav = view.uavs[k];
      targets_[k] = {-1, -1};
      if (uav.failed || uav.in_transit()) {
        actions[k] = sim::Action::kHover;
      } else if (uav.z == 2) {
        actions[k] = sim::Action::kChangePlane;  // inspect everything from close up
      } else {
        targets_[k] = nearest_open_cell(view, uav.pos, k);
        actions[k] =
            targets_[k].x < 0 ? sim::Action::kHover : sim::step_towards(uav.pos, targets_[k]);
      }
    }
  }

 private:
  grid::Cell nearest_open_cell(const sim::PlannerView& view, grid::Cell from,
                               std::size_t uav) const {
    grid::Cell best{-1, -1};
    int best_distance = std::numeric_limits<int>::max();
    const auto& map = view.map;
    for (int y = 0; y < map.height(); ++y) {
      for (int x = 0; x < map.width(); ++x) {
        const auto m = map(x, y);
        if (m != sim::kUnknown && m != sim::kCorrosionSeen) continue;
        const grid::Cell c{x, y};
        const int d = grid::manhattan(from, c);
        if (d >= best_distance || claimed(c, uav)) continue;
        best = c;
        best_distance = d;
      }
    }
    return best;
  }

  bool claimed(grid::Cell c, std::size_t uav) const {
    for (std::size_t j = 0; j < uav; ++j) {
      if (targets_[j].x >= 0 && grid::manhattan(targets_[j], c) < options_.separation) return true;
    }
    return false;
  }

  NearestFirstOptions options_;
  std::vector<grid::Cell> targets_;
};

Params<NearestFirstOptions> nearest_first_params() {
  Params<NearestFirstOptions> p("nearest-first");
  p.integer("separation", &NearestFirstOptions::separation, 0, 1000,
            "smallest Manhattan distance between two UAVs' targets");
  return p;
}

// The one line that makes the planner known everywhere:
const planners::PlannerRegistration registration(make_entry<planners::Planner, NearestFirstOptions>(
    "nearest-first",
    "example user planner (examples/planners): close-up sweep to the nearest open cell",
    nearest_first_params(),
    [](const NearestFirstOptions& o) { return std::make_unique<NearestFirstPlanner>(o); }));

}  // namespace
