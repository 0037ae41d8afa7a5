#pragma once
// A live mission (hullinspect.Session, docs/python.md): the planner and the simulator's bookkeeping
// stepped by the caller, who supplies what the cameras saw instead of a ground truth. This is the
// integration point for a real fleet: each step(readings) takes the readings of the cells sensed
// after the previous actions were flown and returns the next actions.
//
// It reuses the simulator unchanged: the Session owns the "truth" grid the simulator senses from
// and writes each step's readings into it just before the simulator moves the UAVs and senses, so
// M, the counters and the planner's inputs are exactly those of a simulated mission whose truth
// agrees with the readings (tests/python checks this step for step).

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "hullinspect/io/trace_recorder.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/mission_stepper.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/sim/simulator.hpp"

namespace hullinspect::python {

/// One sensed cell as the caller reports it.
struct CellReading {
  int x = 0;
  int y = 0;
  int plane = 2;  ///< the plane the UAV sensed it from (1 close-up, 2 detection)
  bool corroded = false;
};

class Session {
 public:
  /// `prior`: C′ over the hull (-1 not hull, 0, 1). Validates the spec and makes the planner,
  /// which starts at the first step (with the simulator, which senses that step's readings).
  /// With `record_trace`, every step is recorded as `hullinspect run --trace` records a mission.
  Session(std::shared_ptr<const world::HullMask> hull, planners::MissionSpec spec,
          grid::Grid<std::int8_t> prior, bool record_trace = false);
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  /// The cells (x, y, plane) the next step's readings must cover, given the UAVs reported failed
  /// in that step: the footprints of the UAVs that will be on a plane after the pending actions.
  std::vector<std::array<int, 3>> expected_readings(const std::vector<int>& failed) const;

  /// Applies the pending actions (none before the first call), takes `readings` as what the
  /// cameras saw, and returns the next action per UAV; empty once the mission has finished.
  /// Throws Error (nothing changed) if the readings do not cover exactly expected_readings().
  std::vector<sim::Action> step(const std::vector<CellReading>& readings,
                                const std::vector<int>& failed);

  int time() const { return mission_ ? mission_->simulator().time() : 0; }
  bool finished() const { return mission_ && mission_->finished(); }
  bool complete() const { return mission_ && mission_->simulator().complete(); }
  const grid::Grid<std::int8_t>& map() const {
    return mission_ ? mission_->simulator().map() : initial_map_;
  }
  std::span<const sim::UavState> uavs() const {
    return mission_ ? mission_->simulator().uavs() : std::span<const sim::UavState>(initial_uavs_);
  }
  const planners::MissionSpec& spec() const { return spec_; }
  const world::HullMask& hull() const { return *hull_; }
  /// The mission so far as a MissionResult (T_c and c(t) count only the corrosion reported).
  sim::MissionResult result() const;
  /// The trace of the mission so far (docs/trace-format.md; its truth is the readings). Error
  /// unless the session records one and has started.
  nlohmann::json trace() const;

 private:
  void check_readings(const std::vector<CellReading>& readings, const std::vector<int>& failed);

  std::shared_ptr<const world::HullMask> hull_;
  planners::MissionSpec spec_;
  world::Instance instance_;  // truth: the latest reading of each cell; prior: the caller's C′
  std::vector<grid::Cell> starts_;
  std::unique_ptr<planners::Planner> planner_;
  std::optional<io::TraceRecorder> recorder_;
  // The simulator, the planner's context and the flight layers, as every mission builds them;
  // built at the first step, whose readings the simulator senses at t = 0.
  std::optional<planners::MissionStepper> mission_;
  grid::Grid<std::int8_t> initial_map_;
  std::vector<sim::UavState> initial_uavs_;
  std::vector<sim::Action> pending_;  // the actions the last step returned, flown by the next
  // Per-call bookkeeping, sized once: the planes each cell is expected from / was reported from.
  int call_ = 0;
  std::vector<int> stamp_;
  std::vector<std::uint8_t> expected_planes_;
  std::vector<std::uint8_t> reported_planes_;
  std::vector<std::int8_t> reported_value_;
};

}  // namespace hullinspect::python
