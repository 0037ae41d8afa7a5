// The experiment, merge and report commands as a user runs them (the CLI as a child process, found
// through HULLINSPECT_CLI): a run killed with SIGKILL and resumed, the report's files, exit codes
// and one-line errors.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <map>
#include <set>
#include <thread>

#include "experiment_test_support.hpp"
#include "hullinspect/experiment/csv.hpp"
#include "hullinspect/experiment/manifest.hpp"
#include "hullinspect/experiment/results_dir.hpp"
#include "hullinspect/experiment/runner.hpp"

extern char** environ;

namespace hullinspect::experiment {
namespace {

using testing::count_lines;
using testing::read;
using testing::ScratchDir;

std::string cli_path() {
  if (const char* env = std::getenv("HULLINSPECT_CLI"); env != nullptr && *env != '\0') return env;
  // Run by hand from the build tree: the CLI sits beside the test binary (build/<preset>/).
  return (std::filesystem::read_symlink("/proc/self/exe").parent_path() / "hullinspect").string();
}

/// Starts the CLI with `args`, stdout and stderr going to files in `dir`.
pid_t start_cli(const std::vector<std::string>& args, const ScratchDir& dir) {
  std::vector<std::string> argv = {cli_path()};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> raw;
  for (auto& a : argv) raw.push_back(a.data());
  raw.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const std::string out = (dir / "stdout.txt").string();
  const std::string err = (dir / "stderr.txt").string();
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, raw[0], &actions, nullptr, raw.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  EXPECT_EQ(rc, 0) << "cannot start " << raw[0];
  return pid;
}

struct Outcome {
  int status = -1;  ///< exit status, or -signal
  std::string out, err;
};

Outcome wait_cli(pid_t pid, const ScratchDir& dir) {
  int status = 0;
  waitpid(pid, &status, 0);
  Outcome o;
  o.status = WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
  o.out = read(dir / "stdout.txt");
  o.err = read(dir / "stderr.txt");
  return o;
}

std::string read_if_exists(const std::filesystem::path& path) {
  return std::filesystem::exists(path) ? read(path) : std::string();
}

Outcome run_cli(const std::vector<std::string>& args, const ScratchDir& dir) {
  return wait_cli(start_cli(args, dir), dir);
}

/// 2 400 quick lawnmower missions: long enough to be killed part-way.
const char* kLongConfig =
    "hull: rectangle\n"
    "grid: {width: 40, height: 12}\n"
    "scenarios: [{name: dense, p_c: 0.02, l_c: 3}]\n"
    "uavs: [1, 2, 3, 4]\n"
    "instances: 600\n"
    "curve: {step: 20, end: 400}\n";

TEST(ExperimentCli, KilledRunResumesToExactlyTheFullSetOfRows) {
  ScratchDir dir("kill");
  const auto config = dir / "long.yaml";
  io::write_file_atomic(config, kLongConfig);
  const auto out = dir / "results";
  const pid_t pid = start_cli({"experiment", "--config", config.string(), "--out", out.string(),
                               "--jobs", "1"},
                              dir);
  // Kill it once some rows exist.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  int rows = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    std::error_code ec;
    if (std::filesystem::exists(out / kRunsFile, ec)) {
      rows = count_lines(read(out / kRunsFile)) - 1;
      if (rows >= 30) break;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  const Outcome killed = wait_cli(pid, dir);
  ASSERT_EQ(killed.status, -SIGKILL) << "the run finished before it could be killed: " << killed.out;
  const int kept = count_lines(read(out / kRunsFile)) - 1;
  ASSERT_GE(kept, 30);
  ASSERT_LT(kept, 2400);
  EXPECT_EQ(read_manifest(out)["status"], "running");

  const Outcome refused = run_cli({"experiment", "--config", config.string(), "--out", out.string()}, dir);
  EXPECT_EQ(refused.status, 2);
  EXPECT_EQ(refused.err, "hullinspect: " + out.string() +
                             ": is not empty: pass --resume to continue the experiment in it, or "
                             "choose another --out\n");

  const Outcome resumed = run_cli(
      {"experiment", "--config", config.string(), "--out", out.string(), "--resume", "--jobs", "2"}, dir);
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("2400 runs of shard 1/1"), std::string::npos) << resumed.out;

  // Exactly the full set of rows, none duplicated: the same files as an uninterrupted run.
  const ExperimentPlan plan(load_config(config));
  const auto table = parse_csv(read(out / kRunsFile), kRunsFile);
  std::set<std::string> ids;
  for (const auto& r : table.rows) ids.insert(r[0]);
  EXPECT_EQ(table.rows.size(), 2400u);
  EXPECT_EQ(ids.size(), 2400u);
  const auto reference = dir / "reference";
  RunnerOptions options;
  options.jobs = 2;
  run_experiment(plan, reference, options);
  for (const char* file : {kRunsFile, kSamplesFile, kCurvesFile}) {
    EXPECT_EQ(read(out / file), read(reference / file)) << file;
  }
  EXPECT_EQ(read_manifest(out)["status"], "complete");
}

const char* kReportConfig =
    "name: report-test\n"
    "hull: rectangle\n"
    "grid: {width: 30, height: 10}\n"
    "scenarios: [{name: dense, p_c: 0.03, l_c: 3}]\n"
    "sweeps: [{parameter: p_tp, base: dense, values: [1.0, 0.5]}]\n"
    "uavs: [2]\n"
    "algorithms: [lawnmower, {name: lawnmower, label: lm-seed2, options: {partition-seed: 2}}]\n"
    "instances: 3\n"
    "curve: {step: 10, end: 200}\n";

TEST(ExperimentCli, ReportWritesEveryTableAndFigure) {
  ScratchDir dir("report");
  const auto config = dir / "small.yaml";
  io::write_file_atomic(config, kReportConfig);
  const auto results = dir / "results";
  const auto report = dir / "report";
  const Outcome ran = run_cli({"experiment", "--config", config.string(), "--out", results.string()}, dir);
  ASSERT_EQ(ran.status, 0) << ran.err;
  const Outcome made = run_cli({"report", results.string(), "--out", report.string()}, dir);
  ASSERT_EQ(made.status, 0) << made.err;
  EXPECT_NE(made.out.find("### dense — T_c (s), mean ± std over 3 instances"), std::string::npos)
      << made.out;
  // One table per sweep, one row per swept value.
  EXPECT_NE(made.out.find("### sweep of p_tp — T_m (s)"), std::string::npos) << made.out;
  EXPECT_EQ(made.out.find("### p_tp=0.5"), std::string::npos) << made.out;
  EXPECT_NE(made.out.find("| p_tp | s2  | n   | lawnmower"), std::string::npos) << made.out;
  EXPECT_NE(made.out.find("| s2  | n   | lawnmower"), std::string::npos) << made.out;

  EXPECT_EQ(count_lines(read(report / "summary.csv")), 1 + 3 * 2);  // 3 scenarios × 2 algorithms
  const std::string md = read(report / "report.md");
  EXPECT_NE(md.find("# Experiment report: report-test"), std::string::npos);
  EXPECT_TRUE(made.out.starts_with(read(report / "summary.md"))) << made.out;
  // The paired comparisons and the claims (none testable with these algorithms).
  EXPECT_NE(md.find("## The paper's claims"), std::string::npos);
  EXPECT_NE(
      md.find("| C1: Perfect information: Part-TSP achieves considerably smaller T_c than the "
              "other algorithms (V-B.1, Fig. 6 a1) | **not testable** |"),
      std::string::npos)
      << md;
  EXPECT_NE(md.find("### dense, s2 = 7, n = 2"), std::string::npos) << md;
  EXPECT_NE(md.find("| lawnmower − lm-seed2 | 3 | "), std::string::npos) << md;
  EXPECT_EQ(count_lines(read(report / "paired.csv")),
            1 + 3 * 2);  // 3 scenarios × 2 metrics × 1 pair
  for (const std::string stem : {"fig6_dense", "fig7_dense_n2", "fig8_s2-7_n2"}) {
    for (const std::string ext : {".png", ".pdf"}) {
      const auto file = report / "figures" / (stem + ext);
      ASSERT_TRUE(std::filesystem::exists(file)) << file;
      const std::string bytes = read(file);
      EXPECT_GT(bytes.size(), 5000u) << file;
      EXPECT_EQ(bytes.substr(0, 4), ext == ".png" ? "\x89PNG" : "%PDF") << file;
    }
    EXPECT_NE(md.find("![" + stem + "](figures/" + stem + ".png)"), std::string::npos) << stem;
  }
  EXPECT_TRUE(std::filesystem::exists(report / "plot_report.py"));
  // Only these: no figure for anything not in the results.
  int figures = 0;
  for (const auto& f : std::filesystem::directory_iterator(report / "figures")) figures += f.is_regular_file();
  EXPECT_EQ(figures, 6);

  // --planners, --labels, --format, --dpi: one algorithm, SVG only, no pairs to compare.
  const auto chosen = dir / "chosen";
  const Outcome flags =
      run_cli({"report", results.string(), "--out", chosen.string(), "--planners", "lm-seed2",
               "--labels", "lm-seed2=Seeded", "--format", "svg", "--dpi", "80"},
              dir);
  ASSERT_EQ(flags.status, 0) << flags.err;
  EXPECT_EQ(count_lines(read(chosen / "paired.csv")), 1);
  const std::string svg = read(chosen / "figures" / "fig6_dense.svg");
  EXPECT_NE(svg.find("Seeded"), std::string::npos);
  EXPECT_EQ(svg.find("lawnmower"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(chosen / "figures" / "fig6_dense.png"));
  EXPECT_NE(read(chosen / "report.md").find("![fig6_dense](figures/fig6_dense.svg)"),
            std::string::npos);
  const Outcome bad = run_cli(
      {"report", results.string(), "--out", (dir / "bad").string(), "--labels", "zz=Z"}, dir);
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err, "hullinspect: --labels: 'zz' is not an algorithm of the report\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "bad"));

  // A new report into the same directory replaces the earlier figures whole: SVG only now.
  const Outcome again =
      run_cli({"report", results.string(), "--out", report.string(), "--format", "svg"}, dir);
  ASSERT_EQ(again.status, 0) << again.err;
  for (const auto& f : std::filesystem::directory_iterator(report / "figures")) {
    EXPECT_EQ(f.path().extension(), ".svg") << f.path();
  }
  EXPECT_TRUE(std::filesystem::exists(report / "figures" / "fig6_dense.svg"));
}

TEST(ExperimentCli, ErrorsAreOneLineWithExitStatus2) {
  ScratchDir dir("errors");
  const auto bad = dir / "bad.yaml";
  io::write_file_atomic(bad, "s1: 5\ns2:\n  - 7\n  - 8\n");
  const auto out = dir / "never";
  Outcome o = run_cli({"experiment", "--config", bad.string(), "--out", out.string()}, dir);
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "hullinspect: " + bad.string() +
                       ":4: s2: must be an odd integer greater than s1 = 5 (got 8)\n");
  EXPECT_FALSE(std::filesystem::exists(out));

  o = run_cli({"experiment", "--preset", "nope", "--out", out.string()}, dir);
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "hullinspect: --preset: unknown preset 'nope' (known: beyond, fig8, obstacles, paper, paper-quick)\n");

  o = run_cli({"experiment", "--preset", "paper-quick", "--out", out.string(), "--shard", "4/3"}, dir);
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "hullinspect: --shard: must be K/N with 1 <= K <= N (got '4/3')\n");

  o = run_cli({"report", (dir / "nothing").string(), "--out", (dir / "r").string()}, dir);
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "hullinspect: " + (dir / "nothing" / "manifest.json").string() +
                       ": not found (is this a hullinspect experiment directory?)\n");
}

TEST(ExperimentCli, ShardsFromSlurmAndAPartialMerge) {
  ScratchDir dir("slurm");
  const auto config = dir / "small.yaml";
  io::write_file_atomic(config, kReportConfig);
  setenv("SLURM_ARRAY_TASK_ID", "1", 1);
  setenv("SLURM_ARRAY_TASK_COUNT", "2", 1);
  setenv("SLURM_ARRAY_TASK_MIN", "0", 1);
  const Outcome shard = run_cli({"experiment", "--config", config.string(), "--out", (dir / "s2").string()}, dir);
  unsetenv("SLURM_ARRAY_TASK_ID");
  unsetenv("SLURM_ARRAY_TASK_COUNT");
  unsetenv("SLURM_ARRAY_TASK_MIN");
  ASSERT_EQ(shard.status, 0) << shard.err;
  EXPECT_TRUE(shard.err.starts_with("hullinspect: shard 2/2 (from the Slurm job array)\n")) << shard.err;
  EXPECT_EQ(read_manifest(dir / "s2")["shard"], "2/2");
  const Outcome partial = run_cli({"merge", (dir / "s2").string(), "--out", (dir / "m").string()}, dir);
  EXPECT_EQ(partial.status, 3);
  EXPECT_NE(partial.err.find("9 runs of the experiment are in none of the inputs"), std::string::npos)
      << partial.err;
  const Outcome first = run_cli({"experiment", "--config", config.string(), "--out",
                                 (dir / "s1").string(), "--shard", "1/2", "--jobs", "1"},
                                dir);
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.out.find(", 1 job, 0 resumed)\n"), std::string::npos) << first.out;
  const Outcome full = run_cli({"merge", (dir / "s1").string(), (dir / "s2").string(), "--out",
                                (dir / "all").string()},
                               dir);
  EXPECT_EQ(full.status, 0) << full.err;
  EXPECT_EQ(full.out, "merged 2 directories into " + (dir / "all").string() + ": 18 runs\n");
  // One directory is counted in the singular.
  const Outcome single =
      run_cli({"merge", (dir / "all").string(), "--out", (dir / "one").string()}, dir);
  EXPECT_EQ(single.status, 0) << single.err;
  EXPECT_EQ(single.out, "merged 1 directory into " + (dir / "one").string() + ": 18 runs\n");
}

namespace report_checks {

/// Every entry under `dir` with its bytes (files) or kind.
std::map<std::string, std::string> contents(const std::filesystem::path& dir) {
  std::map<std::string, std::string> out;
  if (!std::filesystem::exists(dir)) return out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    out[std::filesystem::relative(e.path(), dir).string()] =
        e.is_regular_file() ? read(e.path()) : "dir";
  }
  return out;
}

/// True when `dir` holds an entry left by a staging directory.
bool staging_left(const std::filesystem::path& dir) {
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().filename().string().find(".staging-") != std::string::npos) return true;
  }
  return false;
}

/// Runs the experiment of kReportConfig (18 runs) from `config` into `results`.
bool run_small_experiment(const ScratchDir& dir, const std::filesystem::path& config,
                          const std::filesystem::path& results) {
  io::write_file_atomic(config, kReportConfig);
  const Outcome o =
      run_cli({"experiment", "--config", config.string(), "--out", results.string()}, dir);
  EXPECT_EQ(o.status, 0) << o.err;
  return o.status == 0;
}

void write_script(const std::filesystem::path& path, const std::string& body) {
  io::write_file_atomic(path, "#!/bin/sh\n" + body);
  std::filesystem::permissions(path, std::filesystem::perms::owner_all);
}

}  // namespace report_checks

TEST(ExperimentCli, ReportRefusesRowsThatLieAndNamesMissingRuns) {
  using report_checks::contents;
  ScratchDir dir("report-rows");
  const auto config = dir / "small.yaml";
  const auto results = dir / "results";
  ASSERT_TRUE(report_checks::run_small_experiment(dir, config, results));
  const std::string runs = read(results / kRunsFile);
  const std::string first =
      runs.substr(runs.find('\n') + 1, runs.find('\n', runs.find('\n') + 1) - runs.find('\n'));
  const std::string id = first.substr(0, first.find(','));

  // A duplicated row (the report would count 4 runs of 3).
  io::write_file_atomic(results / kRunsFile, runs + first);
  const auto report = dir / "report";
  Outcome o = run_cli({"report", results.string(), "--out", report.string(), "--no-figures"}, dir);
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "hullinspect: " + (results / kRunsFile).string() + ":20: run " + id +
                       " appears twice (also on line 2)\n");
  EXPECT_FALSE(std::filesystem::exists(report));
  io::write_file_atomic(results / kRunsFile, runs);

  // A truncated curves.csv is refused in one line, before any Python runs.
  const std::string curves = read(results / kCurvesFile);
  io::write_file_atomic(results / kCurvesFile, curves.substr(0, curves.size() / 2));
  o = run_cli({"report", results.string(), "--out", report.string()}, dir);
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "hullinspect: " + (results / kCurvesFile).string() +
                       ": does not match runs.csv and samples.csv (truncated or edited? merge the "
                       "directory into a new one to rebuild it)\n");
  EXPECT_FALSE(std::filesystem::exists(report));
  io::write_file_atomic(results / kCurvesFile, curves);

  // Half of the runs (one shard): refused, naming the missing runs, unless --partial.
  const auto shard = dir / "shard";
  ASSERT_EQ(run_cli({"experiment", "--config", config.string(), "--out", shard.string(), "--shard",
                     "1/2"},
                    dir)
                .status,
            0);
  o = run_cli({"report", shard.string(), "--out", report.string(), "--no-figures"}, dir);
  EXPECT_EQ(o.status, 2);
  EXPECT_TRUE(o.err.starts_with("hullinspect: " + (shard / kRunsFile).string() +
                                ": 9 of the experiment's 18 runs are missing (run "))
      << o.err;
  EXPECT_TRUE(
      o.err.ends_with(" and 6 more): finish them with --resume or merge the shards, or "
                      "pass --partial\n"))
      << o.err;
  EXPECT_FALSE(std::filesystem::exists(report));
  o = run_cli({"report", shard.string(), "--out", report.string(), "--no-figures", "--partial"},
              dir);
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.err, "hullinspect: " + shard.string() +
                       ": partial report: 9 of the experiment's 18 runs missing\n");
  EXPECT_NE(read(report / "report.md").find("- **Partial**: 9 of the experiment's 18 runs missing"),
            std::string::npos);
}

TEST(ExperimentCli, ReportIsAllOrNothing) {
  using report_checks::contents;
  using report_checks::staging_left;
  using report_checks::write_script;
  ScratchDir dir("report-staging");
  const auto config = dir / "small.yaml";
  const auto results = dir / "results";
  ASSERT_TRUE(report_checks::run_small_experiment(dir, config, results));

  // A Python that fails: nothing is written, and an earlier report is left as it was.
  const auto report = dir / "report";
  Outcome o = run_cli(
      {"report", results.string(), "--out", report.string(), "--python", "/bin/false"}, dir);
  EXPECT_EQ(o.status, 1);
  EXPECT_TRUE(
      o.err.starts_with("hullinspect: --python: plotting failed: /bin/false exited with "
                        "status 1 (is Debian's python3-matplotlib installed?"))
      << o.err;
  EXPECT_EQ(count_lines(o.err), 1);
  EXPECT_FALSE(std::filesystem::exists(report));
  ASSERT_EQ(
      run_cli({"report", results.string(), "--out", report.string(), "--no-figures"}, dir).status,
      0);
  const auto before = contents(report);
  write_script(dir / "fail.sh",
               "echo 'Traceback (most recent call last):' >&2\n"
               "echo 'ValueError: no curves' >&2\nexit 3\n");
  o = run_cli({"report", results.string(), "--out", report.string(), "--python",
               (dir / "fail.sh").string()},
              dir);
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.err, "hullinspect: --python: plotting failed: " + (dir / "fail.sh").string() +
                       " exited with status 3: ValueError: no curves (is Debian's "
                       "python3-matplotlib installed? run scripts/setup, or pass --no-figures)\n");
  EXPECT_EQ(contents(report), before);

  // A Python that hangs is stopped at its time limit.
  write_script(dir / "hang.sh", "exec sleep 600\n");
  o = run_cli({"report", results.string(), "--out", report.string(), "--python",
               (dir / "hang.sh").string(), "--python-timeout", "1"},
              dir);
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.err, "hullinspect: --python: plotting did not finish within 1 s: " +
                       (dir / "hang.sh").string() +
                       " was stopped (raise --python-timeout, or pass --no-figures)\n");
  EXPECT_EQ(contents(report), before);

  // SIGINT or SIGTERM while the Python runs: the child is stopped, nothing is written, and
  // hullinspect ends by the signal.
  for (const int signal : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(signal);
    const auto pid_file = dir / ("child-" + std::to_string(signal) + ".pid");
    write_script(dir / "wait.sh", "echo $$ > '" + pid_file.string() + "'\nexec sleep 600\n");
    const pid_t pid = start_cli({"report", results.string(), "--out", (dir / "fresh").string(),
                                 "--python", (dir / "wait.sh").string()},
                                dir);
    for (int i = 0; i < 1000 && read_if_exists(pid_file).empty(); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    const std::string child = read_if_exists(pid_file);
    ASSERT_FALSE(child.empty()) << "the plotting child never started";
    kill(pid, signal);
    o = wait_cli(pid, dir);
    EXPECT_EQ(o.status, -signal);
    EXPECT_NE(kill(std::stoi(child), 0), 0) << "the child outlived hullinspect";
    EXPECT_FALSE(std::filesystem::exists(dir / "fresh"));
    EXPECT_FALSE(staging_left(dir.path()));
  }

  // A full disk (a file size limit) while writing: nothing of the new report is left.
  const auto sized = dir / "sized";
  std::size_t largest_other = 0;
  for (const char* f : {"summary.csv", "summary.md", "paired.csv"}) {
    largest_other = std::max(largest_other, read(report / f).size());
  }
  const std::size_t blocks = largest_other / 512 + 1;
  ASSERT_GT(read(report / "report.md").size(), blocks * 512)
      << "report.md must be the largest file";
  const std::string command = "trap '' XFSZ; ulimit -f " + std::to_string(blocks) + "; exec '" +
                              cli_path() + "' report '" + results.string() + "' --out '" +
                              sized.string() + "' --no-figures > /dev/null 2> '" +
                              (dir / "err.txt").string() + "'";
  const int status = std::system(command.c_str());
  EXPECT_NE(status, 0);
  EXPECT_NE(read(dir / "err.txt").find("report.md"), std::string::npos) << read(dir / "err.txt");
  EXPECT_FALSE(std::filesystem::exists(sized));
  EXPECT_FALSE(staging_left(dir.path()));
}

TEST(ExperimentCli, AMergeThatHitsAFullDiskLeavesNoDirectory) {
  ScratchDir dir("merge-full");
  const auto config = dir / "small.yaml";
  const auto results = dir / "results";
  ASSERT_TRUE(report_checks::run_small_experiment(dir, config, results));
  const auto merged = dir / "merged";
  const std::string command = "trap '' XFSZ; ulimit -f 1; exec '" + cli_path() + "' merge '" +
                              results.string() + "' --out '" + merged.string() +
                              "' > /dev/null 2> /dev/null";
  EXPECT_NE(std::system(command.c_str()), 0);
  EXPECT_FALSE(std::filesystem::exists(merged));
  EXPECT_FALSE(report_checks::staging_left(dir.path()));
}

}  // namespace
}  // namespace hullinspect::experiment
