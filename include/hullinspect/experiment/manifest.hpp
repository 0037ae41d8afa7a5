#pragma once
// manifest.json: what produced a results directory — tool version, git revision, the full resolved
// config and its fingerprint, shard, host, start and end times and progress.

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>

#include "hullinspect/experiment/plan.hpp"

namespace hullinspect::experiment {

/// UTC time as "YYYY-MM-DDTHH:MM:SSZ".
std::string utc_now();
int host_cores();
std::string host_name();

/// The fields every manifest has: tool, version, git_revision, config_source, config, fingerprint,
/// runs_total, host. Callers add status, shard, times and counts.
nlohmann::json base_manifest(const ExperimentPlan& plan);

/// Reads DIR/manifest.json (InputError naming the file when missing or malformed).
nlohmann::json read_manifest(const std::filesystem::path& dir);
/// Writes DIR/manifest.json atomically.
void write_manifest(const std::filesystem::path& dir, const nlohmann::json& manifest);

}  // namespace hullinspect::experiment
