#include "hullinspect/experiment/results_dir.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/csv.hpp"
#include "hullinspect/experiment/journal.hpp"
#include "hullinspect/experiment/run_row_check.hpp"
#include "hullinspect/files/atomic_file.hpp"

namespace hullinspect::experiment {

namespace {

/// A journal line and its line number in the file.
struct Row {
  std::string text;
  int line = 0;
};

/// The rows of one journal by run id: every id a run of `plan`, none twice, and (for runs.csv)
/// every row a possible record of its run.
std::unordered_map<std::string, Row> by_id(const std::filesystem::path& file,
                                           const JournalRows& rows, const ExperimentPlan& plan,
                                           bool check_runs_rows = false) {
  std::unordered_map<std::string, Row> out;
  int line = 1;
  for (const auto& l : rows.lines) {
    ++line;
    const std::string id(line_id(l));
    if (plan.run_position(id) < 0) {
      throw InputError(file.string(), line,
                       fmt::format("run {} is not part of this experiment (the directory holds "
                                   "another experiment's results)",
                                   id));
    }
    if (check_runs_rows) {
      const int position = plan.run_position(id);
      const auto problem =
          run_row_problem(plan, plan.runs()[static_cast<std::size_t>(position)], l);
      if (!problem.empty()) throw InputError(file.string(), line, problem);
    }
    auto [it, inserted] = out.emplace(id, Row{l, line});
    if (!inserted) {
      throw InputError(file.string(), line,
                       fmt::format("run {} appears twice (also on line {})", id, it->second.line));
    }
  }
  return out;
}

}  // namespace

ExperimentPlan results_plan(const std::filesystem::path& dir, const nlohmann::json& manifest) {
  const auto source = (dir / kManifestFile).string();
  if (!manifest.contains("config")) throw InputError(source, 0, "has no 'config'");
  ExperimentPlan plan(config_from_json(manifest["config"], source));
  if (config_fingerprint(plan.config()) != manifest.value("fingerprint", "")) {
    throw InputError(source, 0,
                     "its config does not reproduce its fingerprint (edited by hand, or written by "
                     "another version of hullinspect?)");
  }
  return plan;
}

StoredRuns read_stored_runs(const std::filesystem::path& dir, const ExperimentPlan& plan,
                            bool finished) {
  StoredRuns stored;
  const auto runs_path = dir / kRunsFile;
  const auto samples_path = dir / kSamplesFile;
  const auto timings_path = dir / kTimingsFile;
  const auto runs = read_journal(runs_path, runs_header());
  const auto samples = read_journal(samples_path, samples_header(plan.config().curve));
  const auto timings = read_journal(timings_path, timings_header());
  for (const auto* j : {&runs, &samples, &timings}) {
    if (j->torn) {
      const auto& name = j == &runs ? runs_path : j == &samples ? samples_path : timings_path;
      if (finished) {
        throw InputError(name.string(), 0, "ends in a line without a line break (truncated?)");
      }
      stored.notes.push_back(fmt::format("{}: dropped a torn last line", name.string()));
    }
  }
  const auto run_lines = by_id(runs_path, runs, plan, true);
  auto sample_lines = by_id(samples_path, samples, plan);
  auto timing_lines = by_id(timings_path, timings, plan);
  int unfinished = 0;
  for (const auto& [id, line] : run_lines) {
    auto s = sample_lines.find(id);
    if (s == sample_lines.end()) {
      if (finished) {
        throw InputError(samples_path.string(), 0,
                         fmt::format("has no row for run {} of runs.csv", id));
      }
      ++unfinished;
      continue;
    }
    const RunKey& run = plan.runs()[static_cast<std::size_t>(plan.run_position(id))];
    const auto problem = samples_row_problem(plan, run, line.text, s->second.text);
    if (!problem.empty()) throw InputError(samples_path.string(), s->second.line, problem);
    RunRecord record;
    record.runs = line.text;
    record.samples = std::move(s->second.text);
    auto t = timing_lines.find(id);
    record.timings = t != timing_lines.end() ? std::move(t->second.text) : id + ",,,,";
    stored.records.emplace(id, std::move(record));
  }
  for (const auto& [id, row] : sample_lines) {
    if (run_lines.contains(id)) continue;
    if (finished) {
      throw InputError(samples_path.string(), row.line,
                       fmt::format("run {} has no row in runs.csv", id));
    }
    ++unfinished;
  }
  if (unfinished > 0) {
    stored.notes.push_back(fmt::format(
        "{}: ignored {} row(s) of runs that had not finished writing", dir.string(), unfinished));
  }
  return stored;
}

OrderedLines canonical_lines(const ExperimentPlan& plan, const StoredRuns& stored) {
  std::vector<std::pair<int, const RunRecord*>> order;
  order.reserve(stored.records.size());
  for (const auto& [id, record] : stored.records)
    order.emplace_back(plan.run_position(id), &record);
  std::sort(order.begin(), order.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  OrderedLines lines;
  for (const auto& [position, record] : order) {
    lines.runs.push_back(record->runs);
    lines.samples.push_back(record->samples);
    lines.timings.push_back(record->timings);
  }
  return lines;
}

void write_final_tables(const std::filesystem::path& dir, const ExperimentPlan& plan,
                        const StoredRuns& stored) {
  const OrderedLines lines = canonical_lines(plan, stored);
  auto write = [&](const char* name, const std::vector<std::string>& header,
                   const std::vector<std::string>& rows) {
    std::string content = csv_line(header) + "\n";
    for (const auto& r : rows) content += r + "\n";
    io::write_file_atomic(dir / name, content);
  };
  write(kSamplesFile, samples_header(plan.config().curve), lines.samples);
  write(kTimingsFile, timings_header(), lines.timings);
  io::write_file_atomic(dir / kCurvesFile, curves_csv(plan, lines));
  write(kRunsFile, runs_header(), lines.runs);
}

bool is_empty_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::exists(dir, ec)) return true;
  if (!std::filesystem::is_directory(dir, ec)) return false;
  return std::filesystem::directory_iterator(dir, ec) == std::filesystem::directory_iterator();
}

}  // namespace hullinspect::experiment
