#pragma once
// Everything that defines one mission, as the CLI and the experiment runner state it.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "hullinspect/core/options.hpp"
#include "hullinspect/planners/mission.hpp"
#include "hullinspect/world/instance.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "hullinspect/world/user_maps.hpp"

namespace hullinspect::planners {

struct MissionSpec {
  /// The default planner of every front door (CLI, experiment configs, Python): the paper's
  /// baseline, which needs no options.
  std::string algorithm = "lawnmower";
  OptionMap planner_options;
  world::MissionParams params;
  world::CorrosionParams corrosion;  ///< zones empty = one default zone
  std::uint64_t seed = 1;
  world::FailurePlan failures;  ///< UAV failures (docs/model.md, "Failures")
  world::UserMaps maps;         ///< the user's prior and/or truth, replacing the generated ones
};

/// Validates `spec` against `hull` (ParameterError naming the field) — params, corrosion, the
/// algorithm name and its options — without running anything. Returns the mission's start cells
/// (world::start_cells, computed once here), which run_mission() takes.
std::vector<grid::Cell> validate(const MissionSpec& spec, const world::HullMask& hull);

/// The statistics a planner may know of the instance's prior (MissionOptions::corrosion):
/// `spec.corrosion`, or null when a user map replaced C' or C (then they describe neither).
const world::CorrosionParams* prior_statistics(const MissionSpec& spec);

/// `options` with the spec's failures and prior statistics where it names none: what run_mission
/// and a live session hand the MissionStepper.
MissionOptions with_spec(const MissionSpec& spec, MissionOptions options);

/// The mission's instance: drawn from spec.seed with spec.corrosion, then spec.maps applied.
world::Instance mission_instance(const MissionSpec& spec, const world::HullMask& hull);

/// The one place a mission is assembled: builds the planner and runs it on `instance` from `starts`
/// with the spec's failures and prior statistics (unless `options` names its own). `spec` must
/// have passed validate(spec, hull), which returned `starts` (a command validates before it
/// declares its outputs); it is not validated again. For callers that watch or change the
/// instance (a trace recorder, `plan`'s world whose truth is the prior).
sim::MissionResult run_mission(const MissionSpec& spec, const world::HullMask& hull,
                               const world::Instance& instance, std::span<const grid::Cell> starts,
                               const MissionOptions& options = {});

/// Validates `spec` (once), draws its instance and runs the mission.
sim::MissionResult run_mission(const MissionSpec& spec, const world::HullMask& hull,
                               const MissionOptions& options = {});

}  // namespace hullinspect::planners
