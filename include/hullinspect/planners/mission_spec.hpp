#pragma once
// Everything that defines one mission, as the CLI and the experiment runner state it.

#include <cstdint>
#include <string>

#include "hullinspect/core/options.hpp"
#include "hullinspect/planners/mission.hpp"
#include "hullinspect/world/instance.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "hullinspect/world/user_maps.hpp"

namespace hullinspect::planners {

struct MissionSpec {
  std::string algorithm = "lawnmower";
  OptionMap planner_options;
  world::MissionParams params;
  world::CorrosionParams corrosion;  ///< zones empty = one default zone
  std::uint64_t seed = 1;
  world::FailurePlan failures;  ///< UAV failures (docs/model.md, "Failures")
  world::UserMaps maps;         ///< the user's prior and/or truth, replacing the generated ones
};

/// Validates `spec` against `hull` (ParameterError naming the field) — params, corrosion, the
/// algorithm name and its options — without running anything.
void validate(const MissionSpec& spec, const world::HullMask& hull);

/// The statistics a planner may know of the instance's prior (MissionOptions::corrosion):
/// `spec.corrosion`, or null when a user map replaced C' or C (then they describe neither).
const world::CorrosionParams* prior_statistics(const MissionSpec& spec);

/// Draws the instance (then applies spec.maps), builds the planner and runs the mission.
sim::MissionResult run_mission(const MissionSpec& spec, const world::HullMask& hull,
                               const MissionOptions& options = {});

}  // namespace hullinspect::planners
