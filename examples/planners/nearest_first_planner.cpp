// A user planner outside src/ (tutorial 04, docs/user-planners.md): "nearest-first" descends to the
// close-up plane and sends each UAV to the nearest cell still unknown or uninspected (M = 0 or 2),
// keeping the fleet's targets `separation` cells apart. Distances and steps come from the mission's
// distance service, so the UAVs fly around no-fly zones and skip cells they cannot inspect. It is
// compiled into the CLI, the tests and the Python module (examples/CMakeLists.txt) and registered
// by the one line at the bottom, so `hullinspect run -a nearest-first`, configs, experiments,
// `hullinspect list` and hullinspect.run_mission(algorithm="nearest-first") all find it.
//
// For brevity it scans the map for targets every step; the built-in planners keep incremental
// sets instead (docs/architecture.md, "Conventions").

#include <cstdint>
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
    distances_ = &planners::distances_of(context, fallback_distances_);
    reach_ = context.reach;
    half_[0] = context.params.s1 / 2;
    half_[1] = context.params.s2 / 2;
  }

  void decide(const sim::PlannerView& view, std::span<sim::Action> actions) override {
    for (std::size_t k = 0; k < actions.size(); ++k) {
      const sim::UavState& uav = view.uavs[k];
      targets_[k] = {-1, -1};
      actions[k] = sim::Action::kHover;
      if (uav.failed || uav.in_transit()) continue;
      grid::Cell viewpoint = grid::kNoCell;
      grid::Cell target = nearest_cell(view, uav.pos, k, Goal::kInspect, viewpoint);
      int plane = 1;
      if (target.x < 0) {
        // Cells no close-up footprint reaches (behind a no-fly zone) are done once seen from z = 2.
        target = nearest_cell(view, uav.pos, k, Goal::kSee, viewpoint);
        plane = 2;
      }
      if (target.x < 0) continue;
      if (uav.z != plane) {
        actions[k] = sim::Action::kChangePlane;
        continue;
      }
      targets_[k] = target;
      actions[k] = sim::step_towards(uav.pos, distances_->next_step(uav.pos, viewpoint));
    }
  }

 private:
  // kInspect: a cell still unknown or seen corroded (M = 0 or 2) that a close-up footprint can
  // reach; kSee: an unknown cell that only a z = 2 footprint can reach.
  enum class Goal { kInspect, kSee };

  bool wanted(const sim::PlannerView& view, grid::Cell c, Goal goal) const {
    const auto m = view.map[c];
    const std::uint8_t reach = reach_ != nullptr ? reach_->reach[c] : world::kReachZ1;
    if (goal == Goal::kInspect) {
      return (m == sim::kUnknown || m == sim::kCorrosionSeen) && (reach & world::kReachZ1) != 0;
    }
    return m == sim::kUnknown && (reach & world::kReachZ1) == 0 && (reach & world::kReachZ2) != 0;
  }

  // The wanted cell whose viewpoint (the cell itself, or the flyable position nearest it within
  // the footprint) is the shortest flight away; `viewpoint` receives that position.
  grid::Cell nearest_cell(const sim::PlannerView& view, grid::Cell from, std::size_t uav, Goal goal,
                          grid::Cell& viewpoint) {
    grid::Cell best{-1, -1};
    int best_distance = std::numeric_limits<int>::max();
    const auto& map = view.map;
    const int half = half_[goal == Goal::kInspect ? 0 : 1];
    const grid::Grid<int>& flight = distances_->field(from);
    for (int y = 0; y < map.height(); ++y) {
      for (int x = 0; x < map.width(); ++x) {
        const grid::Cell c{x, y};
        if (!wanted(view, c, goal)) continue;
        const grid::Cell at = distances_->viewpoint(c, half);
        if (at.x < 0) continue;
        const int d = flight[at];
        if (d >= grid::kUnreachable || d >= best_distance || claimed(c, uav)) continue;
        best = c;
        viewpoint = at;
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
  grid::DistanceService* distances_ = nullptr;
  grid::DistanceService fallback_distances_;
  const world::Reachability* reach_ = nullptr;
  int half_[2] = {0, 0};  // footprint half-widths at z = 1, 2
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
