// The runner end to end (in process): results independent of --jobs, shards merged equal the
// unsharded run, paired seeds, curves from the per-run samples, resume after a torn write, and the
// directory rules.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <set>

#include "experiment_test_support.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/csv.hpp"
#include "hullinspect/experiment/merge.hpp"
#include "hullinspect/experiment/manifest.hpp"
#include "hullinspect/experiment/results_dir.hpp"
#include "hullinspect/experiment/runner.hpp"

namespace hullinspect::experiment {
namespace {

using testing::count_lines;
using testing::kSmallConfig;
using testing::read;
using testing::ScratchDir;

ExperimentPlan small_plan(const std::string& extra = "") {
  return ExperimentPlan(parse_config(std::string(kSmallConfig) + extra, "small.yaml", "."));
}

RunnerSummary run(const ExperimentPlan& plan, const std::filesystem::path& out, int jobs,
                  Shard shard = {}, bool resume = false) {
  RunnerOptions options;
  options.jobs = jobs;
  options.shard = shard;
  options.resume = resume;
  return run_experiment(plan, out, options);
}

CsvTable table(const std::filesystem::path& path) { return parse_csv(read(path), path.string()); }

double number(const std::string& s) {
  double v = 0;
  std::from_chars(s.data(), s.data() + s.size(), v);
  return v;
}

TEST(ExperimentRunner, ResultsDoNotDependOnTheNumberOfJobs) {
  const auto plan = small_plan();
  ScratchDir one("jobs1");
  ScratchDir two("jobs2");
  const auto a = run(plan, one.path(), 1);
  const auto b = run(plan, two.path(), 2);
  EXPECT_EQ(a.total, 96);
  EXPECT_EQ(a.ran, 96);
  EXPECT_EQ(b.ran, 96);
  for (const char* file : {kRunsFile, kSamplesFile, kCurvesFile}) {
    EXPECT_EQ(read(one / file), read(two / file)) << file;
  }
  EXPECT_EQ(count_lines(read(one / kRunsFile)), 97);
  EXPECT_EQ(count_lines(read(one / kTimingsFile)), 97);
  // Rows are in canonical order: the plan's.
  const auto runs = table(one / kRunsFile);
  for (std::size_t i = 0; i < runs.rows.size(); ++i) EXPECT_EQ(runs.rows[i][0], plan.runs()[i].id);
  const auto manifest = read_manifest(one.path());
  EXPECT_EQ(manifest["status"], "complete");
  EXPECT_EQ(manifest["fingerprint"], config_fingerprint(plan.config()));
  EXPECT_EQ(manifest["config"]["seeds"].size(), 6u);
  EXPECT_FALSE(manifest["git_revision"].get<std::string>().empty());
  EXPECT_GE(manifest["host"]["cores"].get<int>(), 1);
  EXPECT_FALSE(std::filesystem::exists(one / ".hullinspect.lock"));
}

TEST(ExperimentRunner, EveryAlgorithmAndParameterSeesTheSameInstances) {
  const auto plan = small_plan();
  ScratchDir dir("paired");
  run(plan, dir.path(), 2);
  const auto runs = table(dir / kRunsFile);
  const int seed = runs.column("seed", "runs.csv");
  const int corroded = runs.column("corroded_cells", "runs.csv");
  const int complete = runs.column("complete", "runs.csv");
  std::map<std::string, std::set<std::string>> corroded_by_seed;
  std::set<std::string> distinct;
  for (const auto& r : runs.rows) {
    corroded_by_seed[r[static_cast<std::size_t>(seed)]].insert(r[static_cast<std::size_t>(corroded)]);
    distinct.insert(r[static_cast<std::size_t>(corroded)]);
    EXPECT_EQ(r[static_cast<std::size_t>(complete)], "1");
  }
  ASSERT_EQ(corroded_by_seed.size(), 6u);
  // Both scenarios have the same zones, so C (and #{C = 1}) depends on the seed alone.
  for (const auto& [s, values] : corroded_by_seed) EXPECT_EQ(values.size(), 1u) << "seed " << s;
  EXPECT_GT(distinct.size(), 1u);  // and the seeds do differ
}

TEST(ExperimentRunner, MergedShardsEqualTheUnshardedRun) {
  const auto plan = small_plan();
  ScratchDir whole("whole");
  run(plan, whole.path(), 2);
  ScratchDir s1("s1"), s2("s2"), s3("s3"), merged("merged"), partial("partial");
  int rows = 0;
  for (int k = 1; k <= 3; ++k) {
    const auto& dir = k == 1 ? s1 : k == 2 ? s2 : s3;
    const auto summary = run(plan, dir.path(), 2, Shard{k, 3});
    EXPECT_EQ(summary.total, 32);
    rows += count_lines(read(dir / kRunsFile)) - 1;
    EXPECT_EQ(read_manifest(dir.path())["shard"], fmt::format("{}/3", k));
  }
  EXPECT_EQ(rows, 96);
  std::filesystem::remove(merged.path());
  const auto summary = merge_results({s3.path(), s1.path(), s2.path()}, merged.path());
  EXPECT_EQ(summary.runs, 96);
  EXPECT_EQ(summary.missing, 0);
  EXPECT_EQ(summary.duplicates, 0);
  for (const char* file : {kRunsFile, kSamplesFile, kCurvesFile}) {
    EXPECT_EQ(read(merged / file), read(whole / file)) << file;
  }
  const auto m = read_manifest(merged.path());
  EXPECT_EQ(m["status"], "complete");
  EXPECT_EQ(m["fingerprint"], read_manifest(whole.path())["fingerprint"]);
  EXPECT_EQ(m["merged_from"].size(), 3u);

  // Two of three shards (one given twice): a partial merge.
  std::filesystem::remove(partial.path());
  const auto p = merge_results({s1.path(), s2.path(), s1.path()}, partial.path());
  EXPECT_EQ(p.runs, 64);
  EXPECT_EQ(p.missing, 32);
  EXPECT_EQ(p.duplicates, 32);
  EXPECT_EQ(read_manifest(partial.path())["status"], "partial");
}

TEST(ExperimentRunner, MergeRefusesAnotherExperimentAndConflictingRows) {
  const auto plan = small_plan();
  const auto other = small_plan("time_limit: 900\n");
  ScratchDir a("a"), b("b"), out("out");
  run(plan, a.path(), 2, Shard{1, 2});
  run(other, b.path(), 2, Shard{2, 2});
  std::filesystem::remove(out.path());
  try {
    merge_results({a.path(), b.path()}, out.path());
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::string(e.what()).find("holds a different experiment than") != std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(out.path()));
  // The same run with different values in two inputs.
  ScratchDir c("c");
  run(plan, c.path(), 2, Shard{1, 2});
  std::string runs = read(c / kRunsFile);
  const auto pos = runs.find(",1,", runs.find('\n'));  // some field of the first row
  runs.replace(pos, 3, ",7,");
  io::write_file_atomic(c / kRunsFile, runs);
  EXPECT_THROW(merge_results({a.path(), c.path()}, out.path()), InputError);
}

TEST(ExperimentRunner, CurvesAreMeansOfThePerRunSamples) {
  const auto plan = small_plan();
  ScratchDir dir("curves");
  run(plan, dir.path(), 2);
  const auto runs = table(dir / kRunsFile);
  const auto samples = table(dir / kSamplesFile);
  const auto curves = table(dir / kCurvesFile);
  ASSERT_EQ(curves.rows.size(), plan.cells().size() * 21);  // t = 0, 10, …, 200
  // Recompute cell 3's c(t) and m(t) at t = 30 from runs.csv and samples.csv.
  const std::string cell = plan.cells()[3].id;
  const int hull = runs.column("hull_cells", "");
  const int corroded = runs.column("corroded_cells", "");
  const int steps = runs.column("steps", "");
  const int inspected30 = samples.column("inspected_30", "");
  const int known30 = samples.column("known_30", "");
  const int known200 = samples.column("known_200", "");
  std::vector<double> c, m;
  for (std::size_t i = 0; i < runs.rows.size(); ++i) {
    const auto& r = runs.rows[i];
    ASSERT_EQ(samples.rows[i][0], r[0]);
    // A finished mission holds its final value: every hull cell known at t = 200 > T_m.
    ASSERT_LT(number(r[static_cast<std::size_t>(steps)]), 200);
    EXPECT_EQ(samples.rows[i][static_cast<std::size_t>(known200)], r[static_cast<std::size_t>(hull)]);
    if (r[1] != cell) continue;
    const double cc = number(r[static_cast<std::size_t>(corroded)]);
    c.push_back(cc == 0 ? 100 : 100 * number(samples.rows[i][static_cast<std::size_t>(inspected30)]) / cc);
    m.push_back(100 * number(samples.rows[i][static_cast<std::size_t>(known30)]) /
                number(r[static_cast<std::size_t>(hull)]));
  }
  ASSERT_EQ(c.size(), 6u);
  auto mean = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
  };
  auto stdev = [&](const std::vector<double>& v) {
    const double mu = mean(v);
    double s = 0;
    for (double x : v) s += (x - mu) * (x - mu);
    return std::sqrt(s / static_cast<double>(v.size() - 1));
  };
  const auto& row = curves.rows[3 * 21 + 3];  // cell 3, t = 30
  EXPECT_EQ(row[0], cell);
  EXPECT_EQ(row[curves.column("t", "")], "30");
  EXPECT_EQ(row[curves.column("runs", "")], "6");
  EXPECT_NEAR(number(row[curves.column("c_mean", "")]), mean(c), 1e-4);
  EXPECT_NEAR(number(row[curves.column("c_std", "")]), stdev(c), 1e-4);
  EXPECT_NEAR(number(row[curves.column("m_mean", "")]), mean(m), 1e-4);
  EXPECT_NEAR(number(row[curves.column("m_std", "")]), stdev(m), 1e-4);
  const auto& last = curves.rows[3 * 21 + 20];  // t = 200: every mission has finished
  EXPECT_EQ(last[curves.column("c_mean", "")], "100.0000");
  EXPECT_EQ(last[curves.column("m_mean", "")], "100.0000");
  EXPECT_EQ(last[curves.column("m_std", "")], "0.0000");
}

TEST(ExperimentRunner, ResumeKeepsFinishedRunsAndDropsTornAndOrphanRows) {
  const auto plan = small_plan();
  ScratchDir full("full");
  run(plan, full.path(), 2);
  // A crash state: 40 finished runs, then a torn runs.csv line, and 5 samples rows of runs whose
  // runs.csv row was never written.
  ScratchDir crashed("crashed");
  std::filesystem::copy(full / kManifestFile, crashed / kManifestFile);
  auto head = [](const std::string& text, int lines) {
    std::size_t pos = 0;
    for (int i = 0; i < lines; ++i) pos = text.find('\n', pos) + 1;
    return text.substr(0, pos);
  };
  const std::string runs = read(full / kRunsFile);
  const std::string torn_line = head(runs, 42).substr(head(runs, 41).size());
  io::write_file_atomic(crashed / kRunsFile,
                        head(runs, 41) + torn_line.substr(0, torn_line.size() / 2));
  io::write_file_atomic(crashed / kSamplesFile, head(read(full / kSamplesFile), 46));
  io::write_file_atomic(crashed / kTimingsFile, head(read(full / kTimingsFile), 46));

  EXPECT_THROW(run(plan, crashed.path(), 2), InputError);  // not empty, no --resume
  std::vector<std::string> notes;
  RunnerOptions options;
  options.jobs = 2;
  options.resume = true;
  options.on_note = [&](const std::string& n) { notes.push_back(n); };
  int progress_calls = 0;
  options.on_progress = [&](const Progress& p) {
    ++progress_calls;
    EXPECT_EQ(p.total, 96);
    EXPECT_EQ(p.resumed, 40);
  };
  const auto summary = run_experiment(plan, crashed.path(), options);
  EXPECT_EQ(summary.resumed, 40);
  EXPECT_EQ(summary.ran, 56);
  EXPECT_EQ(progress_calls, 57);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_TRUE(notes[0].ends_with("runs.csv: dropped a torn last line")) << notes[0];
  EXPECT_TRUE(notes[1].ends_with("ignored 5 row(s) of runs that had not finished writing")) << notes[1];
  for (const char* file : {kRunsFile, kSamplesFile, kCurvesFile}) {
    EXPECT_EQ(read(crashed / file), read(full / file)) << file;
  }
  const auto manifest = read_manifest(crashed.path());
  EXPECT_EQ(manifest["status"], "complete");
  EXPECT_EQ(manifest["resumed"].size(), 1u);
  // Resuming a finished experiment runs nothing and changes nothing.
  const auto again = run(plan, crashed.path(), 2, {}, true);
  EXPECT_EQ(again.ran, 0);
  EXPECT_EQ(read(crashed / kRunsFile), read(full / kRunsFile));
}

TEST(ExperimentRunner, DirectoryRules) {
  const auto plan = small_plan();
  ScratchDir dir("rules");
  io::write_file_atomic(dir / "notes.txt", "mine\n");
  try {
    run(plan, dir.path(), 1);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              dir.path().string() +
                  ": is not empty: pass --resume to continue the experiment in it, or choose "
                  "another --out");
  }
  try {
    run(plan, dir.path(), 1, {}, true);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir / kManifestFile).string() +
                  ": not found (is this a hullinspect experiment directory?)");
  }
  ScratchDir done("done");
  run(plan, done.path(), 2, Shard{1, 2});
  try {
    run(small_plan("time_limit: 900\n"), done.path(), 1, Shard{1, 2}, true);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::string(e.what()).find(": holds results of a different experiment") !=
                std::string::npos)
        << e.what();
  }
  try {
    run(plan, done.path(), 1, Shard{2, 2}, true);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (done / kManifestFile).string() + ": holds shard 1/2, not shard 2/2");
  }
}

}  // namespace
}  // namespace hullinspect::experiment
