#include "hullinspect/experiment/runner.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/output_error.hpp"
#include "hullinspect/experiment/journal.hpp"
#include "hullinspect/experiment/manifest.hpp"
#include "hullinspect/experiment/results_dir.hpp"
#include "hullinspect/planners/partition_cache.hpp"

namespace hullinspect::experiment {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kLockFile = ".hullinspect.lock";

/// An exclusive flock on DIR/.hullinspect.lock, so two runners never append to the same journals.
/// The kernel releases it when the process dies, however it dies.
class DirectoryLock {
 public:
  explicit DirectoryLock(const fs::path& dir) : path_(dir / kLockFile) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw InputError(dir.string(), 0, "cannot create a lock file in it");
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      ::close(fd_);
      throw InputError(dir.string(), 0, "is in use by another hullinspect process");
    }
  }
  ~DirectoryLock() {
    std::error_code ignored;
    fs::remove(path_, ignored);
    ::close(fd_);
  }
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  fs::path path_;
  int fd_ = -1;
};

/// Temporary files of an atomic write that was interrupted ("runs.csv.tmp-1234").
void remove_stale_temporaries(const fs::path& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    for (const char* file : {kRunsFile, kSamplesFile, kTimingsFile, kCurvesFile, kManifestFile}) {
      if (name.starts_with(std::string(file) + ".tmp-")) {
        std::error_code ignored;
        fs::remove(entry.path(), ignored);
      }
    }
  }
}

nlohmann::json open_manifest(const ExperimentPlan& plan, const fs::path& out, bool fresh,
                             const Shard& shard) {
  nlohmann::json manifest = base_manifest(plan);
  manifest["shard"] = shard.text();
  manifest["resumed"] = nlohmann::json::array();
  manifest["started"] = utc_now();
  if (!fresh) {
    const auto old = read_manifest(out);
    const auto manifest_path = (out / kManifestFile).string();
    if (old.value("fingerprint", "") != manifest["fingerprint"]) {
      throw InputError(
          manifest_path, 0,
          fmt::format("holds results of a different experiment (config fingerprint {}; "
                      "this config has {}): choose another --out",
                      old.value("fingerprint", "?"), manifest["fingerprint"].get<std::string>()));
    }
    if (old.value("shard", "1/1") != shard.text()) {
      throw InputError(
          manifest_path, 0,
          fmt::format("holds shard {}, not shard {}", old.value("shard", "1/1"), shard.text()));
    }
    manifest["started"] = old.value("started", manifest["started"].get<std::string>());
    if (old.contains("resumed") && old["resumed"].is_array()) manifest["resumed"] = old["resumed"];
    manifest["resumed"].push_back(utc_now());
  }
  return manifest;
}

}  // namespace

RunnerSummary run_experiment(const ExperimentPlan& plan, const fs::path& out,
                             const RunnerOptions& options) {
  const auto& config = plan.config();
  if (!config.hull) throw LogicError("run_experiment needs a config with its hull mask");
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec)) {
    throw InputError(out.string(), 0, "exists and is not a directory");
  }
  const bool fresh = is_empty_dir(out);
  if (!fresh && !options.resume) {
    throw InputError(out.string(), 0,
                     "is not empty: pass --resume to continue the experiment in it, or choose "
                     "another --out");
  }
  fs::create_directories(out, ec);
  if (ec) throw OutputError(out.string(), fmt::format("cannot create: {}", ec.message()));
  DirectoryLock lock(out);
  remove_stale_temporaries(out);
  nlohmann::json manifest = open_manifest(plan, out, fresh, options.shard);

  RunnerSummary summary;
  summary.jobs = options.jobs > 0 ? options.jobs : host_cores();
  manifest["status"] = "running";
  manifest["jobs"] = summary.jobs;
  int in_shard = 0;
  for (int p = 0; p < static_cast<int>(plan.runs().size()); ++p)
    in_shard += options.shard.contains(p);
  manifest["runs_in_shard"] = in_shard;
  write_manifest(out, manifest);

  // Keep the finished runs, drop torn lines and orphan rows, and continue appending.
  const StoredRuns stored = read_stored_runs(out, plan);
  for (const auto& note : stored.notes) {
    if (options.on_note) options.on_note(note);
  }
  std::vector<int> pending;
  for (int p = 0; p < static_cast<int>(plan.runs().size()); ++p) {
    if (!options.shard.contains(p)) continue;
    ++summary.total;
    if (!stored.records.contains(plan.runs()[static_cast<std::size_t>(p)].id)) pending.push_back(p);
  }
  summary.resumed = summary.total - static_cast<int>(pending.size());
  // Seed-major order: an interrupted experiment has a few instances of every cell, not every
  // instance of a few cells.
  std::stable_sort(pending.begin(), pending.end(), [&](int a, int b) {
    return plan.runs()[static_cast<std::size_t>(a)].seed_index <
           plan.runs()[static_cast<std::size_t>(b)].seed_index;
  });

  planners::PartitionCache cache;
  std::mutex write_mutex;
  std::exception_ptr error;
  const RunKey* failed = nullptr;
  const auto t0 = Clock::now();
  {
    const OrderedLines lines = canonical_lines(plan, stored);
    JournalWriter samples_out(out / kSamplesFile, samples_header(config.curve), lines.samples);
    JournalWriter timings_out(out / kTimingsFile, timings_header(), lines.timings);
    JournalWriter runs_out(out / kRunsFile, runs_header(), lines.runs);

    Progress progress{summary.total, summary.resumed, summary.resumed, 0.0};
    if (options.on_progress) options.on_progress(progress);
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    auto worker = [&] {
      planners::MissionOptions mission_options;
      mission_options.partitions = &cache;
      while (!stop.load()) {
        const std::size_t i = next.fetch_add(1);
        if (i >= pending.size()) break;
        const RunKey& run = plan.runs()[static_cast<std::size_t>(pending[i])];
        try {
          const auto start = Clock::now();
          const auto result =
              planners::run_mission(plan.mission(run), *config.hull, mission_options);
          const double wall = std::chrono::duration<double>(Clock::now() - start).count();
          const RunRecord record = make_record(plan, run, result, wall);
          std::lock_guard guard(write_mutex);
          // runs.csv last: a run counts as finished once its runs.csv row exists.
          samples_out.append(record.samples);
          timings_out.append(record.timings);
          runs_out.append(record.runs);
          ++progress.done;
          ++summary.ran;
          progress.elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
          if (options.on_progress) options.on_progress(progress);
        } catch (...) {
          std::lock_guard guard(write_mutex);
          if (!error) {
            error = std::current_exception();
            failed = &run;
          }
          stop = true;
        }
      }
    };
    const int threads = std::max(1, std::min(summary.jobs, static_cast<int>(pending.size())));
    std::vector<std::jthread> pool;
    for (int j = 0; j < threads; ++j) pool.emplace_back(worker);
  }  // joins the workers, closes the journals
  summary.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  summary.partitions_computed = cache.computed();

  if (error && options.interrupted && options.interrupted()) std::rethrow_exception(error);
  if (error) {
    manifest["status"] = "failed";
    write_manifest(out, manifest);
    const Cell& cell = plan.cells()[static_cast<std::size_t>(failed->cell)];
    std::string what = "unknown error";
    try {
      std::rethrow_exception(error);
    } catch (const std::exception& e) {
      what = e.what();
    } catch (...) {
    }
    throw Error(fmt::format(
        "run {} (scenario {}, algorithm {}, s2 {}, uavs {}, seed {}) failed: {} — the {} finished "
        "runs are kept; fix the cause and continue with --resume",
        failed->id, config.scenarios[static_cast<std::size_t>(cell.scenario)].name,
        config.algorithms[static_cast<std::size_t>(cell.algorithm)].label,
        config.s2[static_cast<std::size_t>(cell.s2)],
        config.uavs[static_cast<std::size_t>(cell.uavs)], failed->seed, what,
        summary.resumed + summary.ran));
  }

  write_final_tables(out, plan, read_stored_runs(out, plan));
  manifest["status"] = "complete";
  manifest["finished"] = utc_now();
  manifest["runs_done"] = summary.total;
  manifest["last_invocation"] = {
      {"missions", summary.ran},
      {"seconds", summary.seconds},
      {"missions_per_second", summary.seconds > 0 ? summary.ran / summary.seconds : 0.0},
      {"jobs", summary.jobs},
      {"partitions_computed", summary.partitions_computed}};
  write_manifest(out, manifest);
  return summary;
}

}  // namespace hullinspect::experiment
