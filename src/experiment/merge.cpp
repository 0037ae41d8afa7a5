#include "hullinspect/experiment/merge.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/manifest.hpp"
#include "hullinspect/experiment/plan.hpp"
#include "hullinspect/experiment/results_dir.hpp"
#include "hullinspect/experiment/staged_dir.hpp"

namespace hullinspect::experiment {

namespace fs = std::filesystem;

MergeSummary merge_results(const std::vector<fs::path>& inputs, const fs::path& out) {
  if (inputs.empty()) throw ParameterError("inputs", "name at least one results directory");
  if (!is_empty_dir(out)) {
    throw InputError(out.string(), 0, "is not empty: merge into a new directory");
  }
  std::vector<nlohmann::json> manifests;
  for (const auto& dir : inputs) manifests.push_back(read_manifest(dir));
  const std::string fingerprint = manifests[0].value("fingerprint", "");
  for (std::size_t i = 1; i < inputs.size(); ++i) {
    if (manifests[i].value("fingerprint", "") != fingerprint) {
      throw InputError((inputs[i] / kManifestFile).string(), 0,
                       fmt::format("holds a different experiment than {} (config fingerprint {} vs "
                                   "{})",
                                   inputs[0].string(), manifests[i].value("fingerprint", "?"),
                                   fingerprint));
    }
  }
  const ExperimentPlan plan = results_plan(inputs[0], manifests[0]);

  MergeSummary summary;
  summary.inputs = static_cast<int>(inputs.size());
  StoredRuns merged;
  for (const auto& dir : inputs) {
    StoredRuns part = read_stored_runs(dir, plan);
    for (auto& note : part.notes) summary.notes.push_back(std::move(note));
    for (auto& [id, record] : part.records) {
      auto [it, inserted] = merged.records.emplace(id, record);
      if (inserted) continue;
      if (it->second.runs != record.runs || it->second.samples != record.samples) {
        throw InputError(dir.string(), 0,
                         fmt::format("run {} differs from the same run in an earlier input", id));
      }
      ++summary.duplicates;
    }
  }
  summary.runs = static_cast<int>(merged.records.size());
  summary.missing = static_cast<int>(plan.runs().size()) - summary.runs;

  // Written whole into a staging directory and renamed into place: a full disk leaves no output
  // directory behind.
  StagedDir staged(out);
  write_final_tables(staged.path(), plan, merged);

  nlohmann::json manifest = base_manifest(plan);
  manifest["config_source"] = manifests[0].value("config_source", "");
  manifest["shard"] = "1/1";
  manifest["status"] = summary.missing == 0 ? "complete" : "partial";
  manifest["runs_done"] = summary.runs;
  manifest["runs_missing"] = summary.missing;
  std::string started;
  std::string finished;
  nlohmann::json parts = nlohmann::json::array();
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const auto& m = manifests[i];
    const std::string s = m.value("started", "");
    const std::string f = m.value("finished", "");
    if (!s.empty() && (started.empty() || s < started)) started = s;
    if (!f.empty() && f > finished) finished = f;
    parts.push_back({{"dir", inputs[i].string()},
                     {"shard", m.value("shard", "1/1")},
                     {"status", m.value("status", "")},
                     {"started", s},
                     {"finished", f},
                     {"git_revision", m.value("git_revision", "unknown")},
                     {"host", m.value("host", nlohmann::json::object())},
                     {"last_invocation", m.value("last_invocation", nlohmann::json::object())}});
  }
  manifest["started"] = started;
  manifest["finished"] = finished;
  manifest["merged_at"] = utc_now();
  manifest["merged_from"] = parts;
  write_manifest(staged.path(), manifest);
  staged.commit();
  return summary;
}

}  // namespace hullinspect::experiment
