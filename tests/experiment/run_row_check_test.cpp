// The row checks that --resume, merge and report share: every row the runner writes passes, and a
// row edited to lie (a parameter, a value out of range, two outcomes that contradict each other,
// a curve sample) is refused with the field and the reason; a run twice in a file is refused, and a
// merge of such a directory writes nothing.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "experiment_test_support.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/csv.hpp"
#include "hullinspect/experiment/merge.hpp"
#include "hullinspect/experiment/results_dir.hpp"
#include "hullinspect/experiment/run_row_check.hpp"
#include "hullinspect/experiment/runner.hpp"

namespace hullinspect::experiment {
namespace {

using testing::kSmallConfig;
using testing::read;
using testing::ScratchDir;

ExperimentPlan small_plan() {
  return ExperimentPlan(parse_config(kSmallConfig, "small.yaml", "."));
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = text.find('\n') + 1;  // after the header
  while (start < text.size()) {
    const auto end = text.find('\n', start);
    out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

/// `line` with the field `column` of `header` set to `value`.
std::string with(const std::string& line, const std::vector<std::string>& header,
                 const std::string& column, const std::string& value) {
  auto fields = *split_csv_line(line);
  const auto at = std::find(header.begin(), header.end(), column);
  EXPECT_NE(at, header.end()) << column;
  fields[static_cast<std::size_t>(at - header.begin())] = value;
  return csv_line(fields);
}

std::string field(const std::string& line, const std::vector<std::string>& header,
                  const std::string& column) {
  const auto fields = *split_csv_line(line);
  const auto at = std::find(header.begin(), header.end(), column);
  return fields[static_cast<std::size_t>(at - header.begin())];
}

class RowCheck : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // (ScratchDir names its directory after the running test: there is none here.)
    dir_ = new std::filesystem::path(std::filesystem::temp_directory_path() /
                                     ("hullinspect-RowCheck-" + std::to_string(::getpid())));
    std::filesystem::remove_all(*dir_);
    plan_ = new ExperimentPlan(small_plan());
    RunnerOptions options;
    options.jobs = 2;
    run_experiment(*plan_, *dir_, options);
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(*dir_);
    delete plan_;
    delete dir_;
  }
  static const RunKey& run_of(const std::string& line) {
    return plan_->runs()[static_cast<std::size_t>(
        plan_->run_position(std::string(line.substr(0, line.find(',')))))];
  }
  /// The first runs.csv row of a mission that took some steps and found corrosion, and its
  /// samples.csv row.
  static std::pair<std::string, std::string> busy_row() {
    const auto runs = lines_of(read(*dir_ / kRunsFile));
    const auto samples = lines_of(read(*dir_ / kSamplesFile));
    const auto h = runs_header();
    for (std::size_t i = 0; i < runs.size(); ++i) {
      if (field(runs[i], h, "steps") != "0" && field(runs[i], h, "corroded_cells") != "0" &&
          field(runs[i], h, "T_c") != "0") {
        return {runs[i], samples[i]};
      }
    }
    ADD_FAILURE() << "no mission with steps and corrosion";
    return {};
  }
  static std::string run_problem(const std::string& line) {
    return run_row_problem(*plan_, run_of(line), line);
  }
  static std::string samples_problem(const std::string& runs, const std::string& samples) {
    return samples_row_problem(*plan_, run_of(runs), runs, samples);
  }
  static inline std::filesystem::path* dir_ = nullptr;
  static inline ExperimentPlan* plan_ = nullptr;
};

TEST_F(RowCheck, EveryRowTheRunnerWritesPasses) {
  const auto runs = lines_of(read(*dir_ / kRunsFile));
  const auto samples = lines_of(read(*dir_ / kSamplesFile));
  ASSERT_EQ(runs.size(), 96u);
  ASSERT_EQ(samples.size(), 96u);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    EXPECT_EQ(run_problem(runs[i]), "") << runs[i];
    EXPECT_EQ(samples_problem(runs[i], samples[i]), "") << samples[i];
  }
}

TEST_F(RowCheck, ARowThatLiesIsRefusedWithItsReason) {
  const auto [row, samples] = busy_row();
  const auto h = runs_header();
  const std::string id = row.substr(0, row.find(','));
  const int limit = plan_->config().mission.time_limit;
  const int hull = plan_->config().hull_cells;
  const std::string t_m = field(row, h, "T_m");
  const std::string t_c = field(row, h, "T_c");
  const int steps = std::stoi(field(row, h, "steps"));
  ASSERT_EQ(hull, 300);
  ASSERT_EQ(field(row, h, "complete"), "1");

  EXPECT_EQ(
      run_problem(with(row, h, "p_tp", "9")),
      fmt::format("p_tp is '9' but run {} of this experiment has '{}'", id, field(row, h, "p_tp")));
  EXPECT_EQ(run_problem(with(row, h, "T_c", "1000000000")),
            fmt::format("T_c must be an integer in [0, {}] (got '1000000000')", limit));
  EXPECT_EQ(run_problem(with(row, h, "hull_cells", "301")),
            "hull_cells must be an integer in [0, 300] (got '301')");
  EXPECT_EQ(run_problem(with(row, h, "complete", "2")),
            "complete must be an integer in [0, 1] (got '2')");
  EXPECT_EQ(run_problem(with(row, h, "moves", "-1")),
            fmt::format("moves must be an integer in [0, {}] (got '-1')", kMaxStoredCount));
  EXPECT_EQ(run_problem(with(row, h, "T_c", std::to_string(steps + 1))),
            fmt::format("T_c is {} but T_m is {} (every corroded cell is inspected once the hull "
                        "is known)",
                        steps + 1, t_m));
  EXPECT_EQ(run_problem(with(row, h, "steps", std::to_string(steps - 1))),
            fmt::format("steps is {} but a complete mission stops at T_m = {}", steps - 1, t_m));
  EXPECT_EQ(run_problem(with(row, h, "T_m", "")),
            "complete is 1 but T_m is empty (a complete mission has a T_m)");
  EXPECT_EQ(run_problem(with(row, h, "complete", "0")),
            fmt::format("complete is 0 but T_m is {} (a mission with a T_m is complete)", t_m));
  EXPECT_EQ(run_problem(with(row, h, "T_c", "")),
            "complete is 1 but T_c is empty (a complete mission has a T_c)");
  EXPECT_EQ(run_problem(with(with(row, h, "hull_cells", "5"), h, "corroded_cells", "6")),
            "corroded_cells is 6 but hull_cells is only 5");
  EXPECT_EQ(run_problem(with(row, h, "redundant_observations", "999999")),
            fmt::format("redundant_observations is 999999 but observations is {}",
                        field(row, h, "observations")));
  EXPECT_EQ(run_problem(with(row, h, "failed_uavs", "3")).substr(0, 37),
            "failed_uavs must be an integer in [0,");
  const std::string many = std::to_string(10 * steps);
  EXPECT_TRUE(
      run_problem(with(row, h, "hovers", many)).starts_with("moves + hovers + steps_transit is "))
      << run_problem(with(row, h, "hovers", many));
  EXPECT_TRUE(run_problem(with(row, h, "steps_z1", many)).starts_with("steps_z1 + steps_z2 is "));
  EXPECT_EQ(
      run_problem(with(row, h, "bound_T_c", "100000")),
      fmt::format("bound_T_c is 100000 but bound_T_m is only {}", field(row, h, "bound_T_m")));
  EXPECT_EQ(run_problem(with(row, h, "failures", "at=3")),
            fmt::format("failures is 'at=3' but run {} of this experiment has '{}'", id,
                        field(row, h, "failures")));
  (void)t_c;
}

TEST_F(RowCheck, SamplesThatCannotBeCountsAreRefused) {
  const auto [row, samples] = busy_row();
  const auto h = samples_header(plan_->config().curve);
  const auto rh = runs_header();
  const std::string hull = field(row, rh, "hull_cells");
  EXPECT_EQ(samples_problem(row, with(samples, h, "known_0", "-3")),
            fmt::format("known_0 must be an integer in [0, {}] (got '-3')", hull));
  // A count that falls: known_10 below known_0.
  const std::string known0 = field(samples, h, "known_0");
  ASSERT_NE(known0, "0");
  EXPECT_EQ(samples_problem(row, with(samples, h, "known_10", "0")),
            fmt::format("known_10 is 0 but the count was already {} (it never decreases)", known0));
  // Every hull cell known before T_m.
  EXPECT_EQ(samples_problem(row, with(samples, h, "known_0", hull)),
            fmt::format("known_0 is {}, the total, but T_m is {}", hull, field(row, rh, "T_m")));
  // Not every hull cell known after T_m.
  EXPECT_EQ(samples_problem(row, with(samples, h, "known_200", "1")),
            fmt::format("known_200 is 1 but the count was already {} (it never decreases)",
                        field(samples, h, "known_190")));
  EXPECT_EQ(samples_problem(row, with(samples, h, "run_id", "x")),
            fmt::format("run_id is 'x', expected '{}'", row.substr(0, row.find(','))));
}

TEST_F(RowCheck, ARunTwiceInAFileIsRefusedAndAMergeOfBadRowsWritesNothing) {
  ScratchDir copy("copy"), out("out");
  std::filesystem::copy(
      *dir_, copy.path(),
      std::filesystem::copy_options::overwrite_existing | std::filesystem::copy_options::recursive);
  const std::string runs = read(copy / kRunsFile);
  const auto rows = lines_of(runs);
  io::write_file_atomic(copy / kRunsFile, runs + rows[0] + "\n");
  std::filesystem::remove(out.path());
  try {
    merge_results({copy.path()}, out.path());
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              fmt::format("{}:98: run {} appears twice (also on line 2)",
                          (copy / kRunsFile).string(), rows[0].substr(0, rows[0].find(','))));
  }
  EXPECT_FALSE(std::filesystem::exists(out.path()));
  // A sample of -3 (curves.csv would then show a spread at t = 0).
  io::write_file_atomic(copy / kRunsFile, runs);
  const std::string samples = read(copy / kSamplesFile);
  const auto sample_rows = lines_of(samples);
  const auto h = samples_header(plan_->config().curve);
  std::string bad = samples;
  bad.replace(bad.find(sample_rows[0]), sample_rows[0].size(),
              with(sample_rows[0], h, "known_0", "-3"));
  io::write_file_atomic(copy / kSamplesFile, bad);
  try {
    merge_results({copy.path()}, out.path());
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::string(e.what()).starts_with((copy / kSamplesFile).string() +
                                                  ":2: known_0 must be an integer in [0, "))
        << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(out.path()));
  // Nothing is left beside the output either (the staging directory is removed).
  for (const auto& e : std::filesystem::directory_iterator(out.path().parent_path())) {
    EXPECT_EQ(e.path().filename().string().find(".staging-"), std::string::npos) << e.path();
  }
}

TEST_F(RowCheck, ResumeRefusesARowThatContradictsItself) {
  ScratchDir copy("resume");
  std::filesystem::copy(
      *dir_, copy.path(),
      std::filesystem::copy_options::overwrite_existing | std::filesystem::copy_options::recursive);
  const std::string runs = read(copy / kRunsFile);
  const auto [row, samples] = busy_row();
  const auto h = runs_header();
  const std::string steps = field(row, h, "steps");
  std::string bad = runs;
  bad.replace(bad.find(row), row.size(), with(row, h, "steps", "0"));
  io::write_file_atomic(copy / kRunsFile, bad);
  RunnerOptions options;
  options.jobs = 1;
  options.resume = true;
  try {
    run_experiment(*plan_, copy.path(), options);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::string(e.what()).ends_with(
        fmt::format("steps is 0 but a complete mission stops at T_m = {}", field(row, h, "T_m"))))
        << e.what();
  }
  EXPECT_EQ(read(copy / kRunsFile), bad) << "the refused results were changed";
}

TEST_F(RowCheck, BatteryColumnsThatLieAreRefused) {
  const auto [row, samples] = busy_row();
  const auto h = runs_header();
  const int steps = std::stoi(field(row, h, "steps"));
  const int uavs = std::stoi(field(row, h, "uavs"));
  ASSERT_EQ(field(row, h, "failed_uavs"), "0");
  EXPECT_EQ(field(row, h, "sorties"), "0");
  EXPECT_EQ(field(row, h, "battery_crashes"), "0");
  EXPECT_EQ(field(row, h, "min_battery_s"), "");
  EXPECT_EQ(run_problem(with(row, h, "battery_crashes", "1")),
            "battery_crashes is 1 but failed_uavs is only 0 (a crash fails the UAV)");
  EXPECT_EQ(run_problem(with(row, h, "min_battery_s", "5")),
            "min_battery_s is 5 but this experiment's flight is unlimited");
  EXPECT_EQ(run_problem(with(row, h, "sorties", "3")),
            "sorties is 3 but this experiment's UAVs start in the air (no launch site)");
  const long long too_long = static_cast<long long>(uavs) * steps + 1;
  EXPECT_EQ(run_problem(with(row, h, "flight_s", std::to_string(too_long))),
            fmt::format("flight_s is {} but {} UAVs × {} steps fly at most {} s", too_long, uavs,
                        steps, too_long - 1));
}

TEST_F(RowCheck, SeparationColumnsThatLieAreRefused) {
  const auto [row, samples] = busy_row();
  const auto h = runs_header();
  ASSERT_EQ(field(row, h, "separation"), "0");
  EXPECT_EQ(field(row, h, "min_separation"), "");
  EXPECT_EQ(field(row, h, "separation_conflicts"), "0");
  const std::string no_separation =
      "but this experiment has no separation (D = 0: the first is empty, the second 0)";
  EXPECT_EQ(run_problem(with(row, h, "min_separation", "3")),
            "min_separation is '3' and separation_conflicts 0 " + no_separation);
  EXPECT_EQ(run_problem(with(row, h, "separation_conflicts", "2")),
            "min_separation is '' and separation_conflicts 2 " + no_separation);
  // A Chebyshev distance on a grid of at most 4096 cells a side.
  EXPECT_EQ(run_problem(with(row, h, "min_separation", "99999999999")),
            "min_separation must be an integer in [0, 4095] (got '99999999999')");
}

}  // namespace
}  // namespace hullinspect::experiment

namespace hullinspect::experiment {
namespace {

// With launch sites T_m is the last landing, after the hull is known: the rows the runner writes
// still pass, and a curve that is complete before T_m is accepted only then.
TEST(RowCheckLaunch, RowsOfMissionsWithLaunchSitesPass) {
  const std::string config =
      std::string(testing::kSmallConfig) + "launch: {sites: [[0, 0], [29, 9]], transfer: 15}\n";
  const ExperimentPlan plan(parse_config(config, "small.yaml", "."));
  const auto dir = std::filesystem::temp_directory_path() /
                   ("hullinspect-RowCheckLaunch-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  RunnerOptions options;
  options.jobs = 2;
  run_experiment(plan, dir, options);
  const auto runs = lines_of(testing::read(dir / kRunsFile));
  const auto samples = lines_of(testing::read(dir / kSamplesFile));
  ASSERT_EQ(runs.size(), 96u);
  const auto h = runs_header();
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto& run = plan.runs()[static_cast<std::size_t>(
        plan.run_position(runs[i].substr(0, runs[i].find(','))))];
    EXPECT_EQ(run_row_problem(plan, run, runs[i]), "") << runs[i];
    EXPECT_EQ(samples_row_problem(plan, run, runs[i], samples[i]), "") << samples[i];
    EXPECT_EQ(field(runs[i], h, "complete"), "1") << runs[i];
    // Out and home: both transfers at least.
    EXPECT_GE(std::stoi(field(runs[i], h, "T_m")), 2 * 15) << runs[i];
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hullinspect::experiment
