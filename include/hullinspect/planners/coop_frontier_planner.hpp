#pragma once
// Coop-Frontier (model.md §5.4; paper Section IV-B): fully cooperative frontier-based inspection on
// the shared map M, with frontier utilities from the prior and from detections (eq. 13), a greedy
// robot–frontier assignment with utility reduction (eqs. 15–17) and close-up inspection of detected
// corrosion. No partition, so the fleet keeps working when UAVs fail.

#include <cstdint>
#include <optional>
#include <vector>

#include "hullinspect/planners/coop_frontier_assignment.hpp"
#include "hullinspect/planners/coop_frontier_cell_set.hpp"
#include "hullinspect/planners/coop_frontier_claims.hpp"
#include "hullinspect/planners/coop_frontier_distance_floor.hpp"
#include "hullinspect/planners/coop_frontier_fields.hpp"
#include "hullinspect/planners/coop_frontier_frontiers.hpp"
#include "hullinspect/planners/flight_distances.hpp"
#include "hullinspect/planners/planner.hpp"

namespace hullinspect::planners {

struct CoopFrontierOptions {
  /// α of eq. 13: weight of the prior term 1/d_HP against the detection term 1/d_C, in [0, 1].
  /// Tuned on seeds 1001–1030 (docs/coop-frontier.md; the spec's untuned value is 0.5).
  double alpha = 1.0;
  /// β of eq. 15: weight of the travel term 1/d(r, f), ≥ 0. Tuned with α (untuned: 1.0).
  double beta = 4.0;
  /// γ ≥ 0 added to every frontier's utility: U_f = γ + eq. 13. The paper has none (γ = 0); with
  /// γ > 0 the reductions of eq. 16 keep spreading the fleet once no prior is left to see and no
  /// detection is waiting, where eq. 13 is 0 everywhere. Tuned with α and β
  /// (docs/coop-frontier.md).
  double base_utility = 0.5;
  /// Close-up radius of the INSPECT target rule in units of Δζ (the paper's 2·Δζ), ≥ 0.
  double radius_factor = 2.0;
  /// End game (F empty): an INSPECT UAV whose target set is empty takes the nearest unclaimed
  /// M = 2 cell at z = 1 instead of ascending only to descend again (docs/coop-frontier.md).
  bool endgame_stay_low = false;
};

class CoopFrontierPlanner final : public Planner {
 public:
  enum class Mode : std::uint8_t {
    kExplore,  ///< z = 2 (or ascending to it): flies to a frontier target
    kInspect,  ///< z = 1 (or descending to it): visits corrosion cells
    kFailed,   ///< the UAV failed: no target, no claims
  };

  explicit CoopFrontierPlanner(CoopFrontierOptions options = {}) : options_(options) {}
  void start(const PlannerContext& context) override;
  void decide(const sim::PlannerView& view, std::span<sim::Action> actions) override;
  sim::PlannerStats stats() const override;
  void annotate(AnnotationSink& sink) const override;

  // Read access for tests and tools.
  const CoopFrontierOptions& options() const { return options_; }
  Mode mode(int uav) const { return uavs_[static_cast<std::size_t>(uav)].mode; }
  /// The frontier an EXPLORE UAV flies to, or the cell an INSPECT UAV visits; nullopt when none.
  std::optional<grid::Cell> target(int uav) const;
  const FrontierSet& frontiers() const { return frontiers_; }
  const InspectionClaims& claims() const { return claims_; }
  /// The close-up radius in cells: floor(radius_factor · Δζ).
  int close_up_radius() const { return radius_; }
  /// Distance transforms run so far for d_HP and d_C together.
  long long transforms() const { return prior_field_.transforms() + detected_field_.transforms(); }

 private:
  struct UavPlan {
    Mode mode = Mode::kExplore;
    grid::Cell target{-1, -1};    ///< x < 0: none
    bool changing_plane = false;  ///< in transit or told to change plane this step (annotate())
    bool has_target() const { return target.x >= 0; }
  };

  /// M as this planner works with it: with no-fly zones, a cell no z = 2 footprint reaches and a
  /// corroded one no z = 1 footprint reaches read 1 (nothing is left to do there).
  std::int8_t effective(int index, std::int8_t m) const;
  /// The next position from `pos` towards the allowed place that sees `target` on plane z.
  grid::Cell step_to(int uav, grid::Cell pos, grid::Cell target, int z);
  /// Whether UAV `uav`'s part of the flight space sees cell `index` with footprint half-width
  /// `half` (always, unless no-fly zones cut the flight space into parts).
  bool sees(int uav, int index, int half);
  /// The service's distance field from `pos` with no-fly zones; null (Manhattan) without.
  const grid::Grid<int>* field_from(int uav, grid::Cell pos);
  void absorb_readings(const sim::PlannerView& view);
  bool claim_detections(int uav, const sim::PlannerView& view);
  std::optional<grid::Cell> claim_nearest_free(int uav, grid::Cell pos);
  void assign_frontiers();
  /// A lower bound on d_HP over F (grid::kUnreachable when no prior cell is left unseen).
  int prior_floor();
  void start_end_game(const sim::PlannerView& view, std::span<sim::Action> actions);

  CoopFrontierOptions options_;
  int width_ = 0;
  int radius_ = 0;
  std::vector<UavPlan> uavs_;

  grid::DistanceService* distances_ = nullptr;  // the mission's, or own_distances_
  grid::DistanceService own_distances_;
  FlightDistances flights_;                                // per UAV: its part's service
  std::vector<grid::DistanceService*> uav_distances_;      // flights_.of(k)
  std::vector<grid::DistanceService*> needing_distances_;  // parallel to needing_pos_ (parts only)
  const grid::Grid<std::uint8_t>* reach_ = nullptr;        // no-fly zones only: kReachZ1/Z2 bits
  int half1_ = 0;
  int half2_ = 0;

  // What the fleet knows, mirrored from the readings so nothing is rescanned per step.
  grid::Grid<std::int8_t> map_;         // effective() M
  std::vector<std::uint8_t> known_;     // M ≠ 0 (non-hull counts as known)
  std::vector<std::uint8_t> absorbed_;  // a reading of the cell has been taken in
  FrontierSet frontiers_;               // F
  SourceDistanceField prior_field_;     // prior corrosion not yet seen by any UAV → d_HP
  SourceDistanceField detected_field_;  // detected (seen, M = 2) and not inspected → d_C
  DistanceFloor prior_floor_;           // a lower bound on d_HP over F
  IndexedCellSet corrosion_left_;       // every cell with M = 2 (end game)
  InspectionClaims claims_;

  // Per-step scratch, reserved in start().
  FrontierAssigner assigner_;
  std::vector<int> joined_;  // cells that joined F since the last assignment
  std::vector<grid::Cell> held_;
  std::vector<grid::Cell> needing_pos_;
  std::vector<int> needing_uav_;
  std::vector<int> chosen_;
  long long assignments_ = 0;
};

}  // namespace hullinspect::planners
