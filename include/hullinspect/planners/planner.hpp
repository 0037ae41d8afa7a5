#pragma once
// The Planner stage: one action per UAV per step, from what the UAVs know (never the ground truth).

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/core/options.hpp"
#include "hullinspect/core/registry.hpp"
#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/partition/partitioner.hpp"
#include "hullinspect/sim/mission_result.hpp"
#include "hullinspect/sim/planner_view.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/instance.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "hullinspect/world/no_fly.hpp"

namespace hullinspect::planners {

/// Supplies partitions; the experiment runner passes a cache so that missions sharing hull, starts,
/// n and partition seed compute the partition once.
class PartitionSource {
 public:
  virtual ~PartitionSource() = default;
  virtual std::shared_ptr<const partition::Partition> get(
      std::string_view partitioner, const OptionMap& options,
      const partition::PartitionRequest& request) = 0;
};

/// Computes every partition afresh.
class DirectPartitionSource final : public PartitionSource {
 public:
  std::shared_ptr<const partition::Partition> get(
      std::string_view partitioner, const OptionMap& options,
      const partition::PartitionRequest& request) override;
};

/// What a planner knows before take-off.
struct PlannerContext {
  const world::HullMask& hull;
  const world::MissionParams& params;
  const grid::Grid<std::int8_t>& prior;  ///< C' (−1 not hull, 0, 1)
  std::span<const grid::Cell> starts;    ///< the UAVs' start cells
  PartitionSource& partitions;
  /// The mission's one distance service (docs/model.md, "No-fly zones"): every distance and path a
  /// planner uses comes from it. run_mission() always sets it; null (hand-built contexts in tests)
  /// means no no-fly positions — use planners::distances_of().
  grid::DistanceService* distances = nullptr;
  /// Which hull cells can be inspected / detected at all; null: every one.
  const world::Reachability* reach = nullptr;
  /// The ground truth C — only for planners whose sees_truth() is true (oracle bounds); else null.
  const grid::Grid<std::int8_t>* truth = nullptr;
  /// The statistics the instance was drawn with (zones' p_C, l_C, the prior's p_TP, p_FP) — what
  /// an operator knows of the prior's quality, never C itself; null when unknown (a user's map).
  /// Only the prior-aware partition reads it (planners/prior_weights.hpp).
  const world::CorrosionParams* corrosion = nullptr;
};

/// Adds the mission's no-fly zones to a partition request (DARP's initial distances then follow
/// the shortest allowed flights, and each flight component's cells go to its own UAVs), and the
/// distance service's neighbour flights on an unrolled hull; nothing without either.
void add_no_fly(partition::PartitionRequest& request, const PlannerContext& context);

/// The context's distance service, or `fallback` (reset to an obstacle-free one of the hull's
/// size) when the context has none.
grid::DistanceService& distances_of(const PlannerContext& context, grid::DistanceService& fallback);

/// Receives what a planner wants shown in traces and the viewer; only called when tracing.
class AnnotationSink {
 public:
  virtual ~AnnotationSink() = default;
  /// A UAV's mode (e.g. "cover", "inspect", "explore"), current target (x < 0: none) and plan
  /// (waypoints still ahead).
  virtual void uav(int k, std::string_view mode, grid::Cell target,
                   std::span<const grid::Cell> plan) = 0;
  /// A named set of cells (e.g. "frontiers"), as flat indices.
  virtual void cells(std::string_view layer, std::span<const int> indices) = 0;
};

class Planner {
 public:
  virtual ~Planner() = default;
  /// Called once before t = 0's decision.
  virtual void start(const PlannerContext& context) = 0;
  /// The main hook: fills one action per UAV from the view at time t.
  virtual void decide(const sim::PlannerView& view, std::span<sim::Action> actions) = 0;
  /// UAVs the planner sends home for a battery swap before this step's decision (docs/model.md,
  /// "Batteries and sorties"), appended to `uavs`: only working UAVs airborne on the hull, and
  /// only when view.returns.limited(). Called before decide(); the sortie layer then sends home,
  /// as its safety net, any other UAV whose battery is at ReturnRule::battery_needed. The
  /// default plans none: the layer alone decides.
  virtual void returns(const sim::PlannerView& /*view*/, std::vector<int>& /*uavs*/) {}
  /// True only for oracle planners (name "oracle-…"): run_mission then hands them the truth C.
  virtual bool sees_truth() const { return false; }
  /// True when every UAV that has not failed will only hover from now on, whatever it senses: the
  /// mission then ends (incomplete if the hull is not done). Called after each step.
  virtual bool idle(const sim::PlannerView& /*view*/) const { return false; }
  /// Counters for the mission result.
  virtual sim::PlannerStats stats() const { return {}; }
  /// The partition used, for partitioned planners (traces and viewer).
  virtual const partition::Partition* partition() const { return nullptr; }
  /// Reports modes, targets and plans; called after decide() when tracing.
  virtual void annotate(AnnotationSink& /*sink*/) const {}
};

using PlannerInfo = RegistryEntry<Planner>;
using PlannerRegistry = Registry<Planner>;

/// Every planner by name. Add your own (docs/user-planners.md) with
/// `static const planners::PlannerRegistration reg(make_entry<Planner, MyOptions>(…));`
/// or planners().add(…) before use.
PlannerRegistry& planners();
/// A snapshot of planners().entries().
std::vector<PlannerInfo> planner_registry();
/// Throws ParameterError("algorithm", …) for an unknown name, or ("<name>.<option>", …).
std::unique_ptr<Planner> make_planner(std::string_view name, const OptionMap& options = {});
/// The effective options of a planner: validated, every default filled in, canonical text
/// (nested groups such as "tsp.<key>" expanded for the chosen solver/partitioner).
OptionMap resolve_planner_options(std::string_view name, const OptionMap& options = {});

/// Registers a planner at static-initialisation time (one line in the planner's own file).
struct PlannerRegistration {
  explicit PlannerRegistration(PlannerInfo entry);
};

}  // namespace hullinspect::planners
