#pragma once
// Records a mission as a JSON trace (docs/trace-format.md): instance, parameters, partition, the
// UAV states of every step, the cells each step changed and the planner's annotations (only when
// they change), so a viewer can rebuild any time step.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "hullinspect/planners/mission.hpp"
#include "hullinspect/world/instance.hpp"

namespace hullinspect::io {

class TraceRecorder final : public planners::MissionObserver, private planners::AnnotationSink {
 public:
  /// `parameters` is copied into the trace as given (algorithm, options, seed, instance parameters).
  TraceRecorder(const world::Instance& instance, nlohmann::json parameters);

  void on_start(const sim::Simulator& sim, const planners::Planner& planner) override;
  void on_step(const sim::Simulator& sim, const planners::Planner& planner) override;

  /// The whole trace, with the mission's result.
  nlohmann::json finish(const sim::MissionResult& result) const;

 private:
  void uav(int k, std::string_view mode, grid::Cell target, std::span<const grid::Cell> plan) override;
  void cells(std::string_view layer, std::span<const int> indices) override;
  nlohmann::json frame(const sim::Simulator& sim, const planners::Planner& planner);

  const world::Instance& instance_;
  nlohmann::json trace_;
  nlohmann::json steps_ = nlohmann::json::array();
  // Last annotations written, to write only changes.
  std::vector<nlohmann::json> last_uav_;
  std::vector<std::pair<std::string, std::vector<int>>> last_layers_;
  nlohmann::json pending_uavs_;
  nlohmann::json pending_layers_;
};

}  // namespace hullinspect::io
