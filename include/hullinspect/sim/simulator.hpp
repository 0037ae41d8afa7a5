#pragma once
// The simulator owns the ground truth C and the mission map M. It applies one action per UAV per
// step, senses (model.md §3) and records the metrics incrementally (model.md §4). It never rescans
// the grid after construction and allocates nothing per step.

#include <span>
#include <vector>

#include "hullinspect/grid/flight_steps.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/sim/mission_result.hpp"
#include "hullinspect/sim/planner_view.hpp"
#include "hullinspect/sim/return_rule.hpp"
#include "hullinspect/sim/types.hpp"
#include "hullinspect/world/battery.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/instance.hpp"
#include "hullinspect/world/launch_sites.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "hullinspect/world/no_fly.hpp"

namespace hullinspect::sim {

class Simulator {
 public:
  /// Places the UAVs on `starts` (world::start_cells of the mission, computed once by its caller)
  /// at start_z and senses (t = 0). `params` must be valid.
  Simulator(const world::HullMask& hull, const world::Instance& instance,
            const world::MissionParams& params, std::span<const grid::Cell> starts);
  /// The same on world::start_cells(params, hull).
  Simulator(const world::HullMask& hull, const world::Instance& instance,
            const world::MissionParams& params);

  /// Applies one action per UAV (ignored for UAVs in transit or failed), senses, advances t. A move
  /// to a neighbour k steps away (flight_steps()) arrives at once and keeps the UAV in transit for
  /// k − 1 more steps.
  /// Throws LogicError if an action would leave the grid or enter a no-fly position (a planner
  /// error), the mission is already finished, or, with strict_separation, two UAVs conflict.
  void step(std::span<const Action> actions);

  /// UAV `uav` fails at the start of step `from_time` (t → t+1): from then on its actions are
  /// ignored, it stays put (a UAV in transit stays in transit) and senses nothing. The UAV reads
  /// `failed` in the view from t+1 on. Call before the step; the latest call for a UAV wins.
  void fail_uav_at(int uav, int from_time);

  /// The sortie layer (sim/sortie_layer.hpp) sends UAV `uav` home before the step at t: it climbs
  /// to plane 2, flies to its launch site, lands, swaps its battery, takes off and flies back to
  /// its position and plane (the one it was changing to, if it was changing), away meanwhile.
  /// Throws LogicError without launch sites, or for a UAV that failed or is already away.
  void return_for_swap(int uav);
  /// The UAVs' batteries in steps (not limited in the paper's model).
  const world::BatterySteps& battery() const { return battery_; }

  int time() const { return time_; }
  /// Every counted cell known: the hull cells that can reach their final state (docs/model.md).
  bool complete() const { return known_ == hull_cells_; }
  /// Complete and, with launch sites, every working UAV landed; at the time limit; or no UAV left
  /// that can act (every UAV failed).
  bool finished() const {
    return (complete() && !homing_) || time_ >= params_.time_limit ||
           failed_ == static_cast<int>(uavs_.size());
  }
  /// The UAVs' launch sites and legs (empty without launch sites).
  const world::LaunchLegs& launch_legs() const { return legs_; }
  int failed_uavs() const { return failed_; }
  const world::MissionParams& params() const { return params_; }
  const world::HullMask& hull() const { return hull_; }
  /// The start cell of each UAV.
  std::span<const grid::Cell> starts() const { return starts_; }
  int plane_change_steps() const { return uz_; }
  /// Steps of each neighbour flight per plane (empty: every flight one step).
  const grid::FlightSteps& flight_steps() const { return flights_; }
  /// Flyable positions and the hull cells that can be inspected / detected (computed at t = 0).
  const world::Reachability& reachability() const { return reach_; }
  /// True when (x, y) is a no-fly position of the mission.
  bool no_fly(grid::Cell c) const { return params_.no_fly && (*params_.no_fly)[c] != 0; }

  /// What the UAVs know — the only thing planners see.
  PlannerView view() const { return {time_, uavs_, map_, seen_, log_, return_rule()}; }
  /// When the sortie layer sends a UAV home (not limited() without a battery or launch sites).
  ReturnRule return_rule() const { return {legs_, battery_, world::sortie_margin_steps(params_)}; }
  std::span<const UavState> uavs() const { return uavs_; }
  const grid::Grid<std::int8_t>& map() const { return map_; }
  /// Flat indices of the cells whose M changed in the last step (or at t = 0).
  std::span<const int> changed_cells() const { return changed_; }
  /// Actions applied in the last step (after ignoring busy and failed UAVs: those read kHover).
  std::span<const Action> applied_actions() const { return applied_; }

  double c_percent() const;
  double m_percent() const;
  int inspected_corroded() const { return inspected_; }
  long long separation_conflicts() const { return result_.separation_conflicts; }
  std::optional<int> min_separation() const { return result_.min_separation; }
  int known_cells() const { return known_; }

  /// The mission's result so far (complete when finished()).
  MissionResult result() const;

 private:
  void sense_all();
  void sense(int uav);
  void record_metrics();
  // Launch sites (docs/model.md): the positions a UAV flies while away, one per step.
  void advance_away(std::size_t k);
  void start_homing();
  /// Appends to away_path_[k] the flight home from the UAV's state: climb, fly, land, transfer;
  /// the last entry is on the ground. Returns the site's cell.
  grid::Cell append_flight_home(std::size_t k);
  void use_battery(std::size_t k, bool was_airborne);
  void check_separation();

  const world::HullMask& hull_;
  const grid::Grid<std::int8_t>& truth_;
  world::MissionParams params_;
  std::vector<grid::Cell> starts_;
  world::Reachability reach_;
  int uz_ = 1;
  grid::FlightSteps flights_;
  int time_ = 0;

  grid::Grid<std::int8_t> map_;
  grid::Grid<std::uint8_t> seen_;
  grid::Grid<std::uint8_t> counted_;  // 1: the cell counts in c(t) / m(t)
  std::vector<UavState> uavs_;
  std::vector<int> fail_time_;
  std::vector<Action> applied_;
  std::vector<grid::Cell> previous_;  // positions before the step, for exchanges of cells
  SensingLog log_;
  std::vector<int> changed_;

  int hull_cells_ = 0;
  int corroded_ = 0;
  int inspected_ = 0;
  int known_ = 0;
  int failed_ = 0;
  MissionResult result_;  // series and counters, filled as the mission runs
  world::LaunchLegs legs_;
  // One step of a UAV away from the hull: where it is, on which plane, and whether airborne, at
  // the step's end; kSwapped marks the step that ends a battery swap.
  static constexpr std::uint8_t kAirborne = 1;
  static constexpr std::uint8_t kSwapped = 2;
  struct AwayStep {
    grid::Cell pos;
    std::int8_t z = 2;
    std::uint8_t flags = kAirborne;
  };
  std::vector<std::vector<AwayStep>> away_path_;  // per UAV: its state at each step away
  std::vector<std::size_t> away_next_;            // per UAV: the next entry of away_path_
  // Per UAV: it is on the ground while its next entry of away_path_ lies in [landed_end_,
  // out_begin_] (landed, swapping); from out_begin_ on it flies out (at the start of the mission,
  // or after a swap).
  std::vector<std::size_t> landed_end_;
  std::vector<std::size_t> out_begin_;
  world::BatterySteps battery_;
  bool homing_ = false;  // the hull is complete and some working UAV has not landed yet
};

}  // namespace hullinspect::sim
