#pragma once
// Records a mission as a JSON trace (docs/trace-format.md): instance, parameters, partition, the
// UAV states of every step, the cells each step changed and the planner's annotations (only when
// they change), so a viewer can rebuild any time step. Layers are written as changes (cells added
// and removed) with the whole set at least every kLayerKeyframeInterval frames, so a trace grows
// with what changed, not with the size of the layers.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/world/instance.hpp"

namespace hullinspect::io {

/// A layer's whole set is written when it changes and its last whole set is this many frames old
/// or more, so a reader rebuilds any frame from at most this many frames minus one of changes.
inline constexpr int kLayerKeyframeInterval = 128;

class TraceRecorder final : public planners::MissionObserver, private planners::AnnotationSink {
 public:
  /// `parameters` is copied into the trace as given (algorithm, options, seed, instance
  /// parameters).
  TraceRecorder(const world::Instance& instance, nlohmann::json parameters);

  void on_start(const sim::Simulator& sim, const planners::Planner& planner) override;
  void on_step(const sim::Simulator& sim, const planners::Planner& planner) override;

  /// The whole trace, with the mission's result.
  nlohmann::json finish(const sim::MissionResult& result) const;

 private:
  void uav(int k, std::string_view mode, grid::Cell target,
           std::span<const grid::Cell> plan) override;
  void cells(std::string_view layer, std::span<const int> indices) override;
  nlohmann::json frame(const sim::Simulator& sim, const planners::Planner& planner);

  const world::Instance& instance_;
  nlohmann::json trace_;
  nlohmann::json steps_ = nlohmann::json::array();
  // Last annotations written, to write only changes.
  std::vector<nlohmann::json> last_uav_;
  struct LayerState {
    std::string name;
    std::vector<int> cells;  // sorted
    int last_full = -1;      // frame of the last whole set written, -1 before the first
  };
  std::vector<LayerState> last_layers_;
  std::vector<int> sorted_, added_, removed_;  // scratch of cells()
  nlohmann::json pending_uavs_;
  nlohmann::json pending_layers_;
  int frame_index_ = 0;
  bool physical_ = false;  // launch sites: the frames carry kPhysicalUavFields
};

}  // namespace hullinspect::io
