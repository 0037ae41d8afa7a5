// hullinspect experiment: run a config or preset's missions in parallel into a results directory
// (resumable, shardable); registers merge and report too.

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>

#include "experiment_commands.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/plural.hpp"
#include "hullinspect/experiment/build_data.hpp"
#include "hullinspect/experiment/presets.hpp"
#include "hullinspect/experiment/runner.hpp"
#include "hullinspect/files/output_set.hpp"
#include "number_options.hpp"
#include "progress_reporter.hpp"

namespace hullinspect::cli {

namespace {

/// The instance seeds for --dry-run: "seed 7", "seeds 1–50" when consecutive, else the first
/// few ("seeds 3, 9, 4, …").
std::string seeds_text(const std::vector<std::uint64_t>& seeds) {
  if (seeds.size() == 1) return fmt::format("seed {}", seeds.front());
  bool consecutive = true;
  for (std::size_t i = 1; i < seeds.size(); ++i)
    consecutive &= seeds[i - 1] != UINT64_MAX && seeds[i] == seeds[i - 1] + 1;
  if (consecutive) return fmt::format("seeds {}–{}", seeds.front(), seeds.back());
  constexpr std::size_t kShown = 3;
  std::string text = "seeds ";
  for (std::size_t i = 0; i < std::min(seeds.size(), kShown); ++i)
    text += fmt::format("{}{}", i > 0 ? ", " : "", seeds[i]);
  return seeds.size() > kShown ? text + ", …" : text;
}

struct ExperimentArgs {
  std::string preset;
  std::string config;
  std::string out;
  int jobs = 0;
  bool resume = false;
  std::string shard;
  std::vector<std::string> algorithms;
  int instances = 0;
  std::optional<std::uint64_t> first_seed;
  bool dry_run = false;
  bool list_presets = false;
};

experiment::ExperimentConfig load(const ExperimentArgs& a) {
  if (a.preset.empty() == a.config.empty()) {
    throw ParameterError("preset", "give exactly one of --preset NAME or --config FILE");
  }
  auto config =
      a.preset.empty() ? experiment::load_config(a.config) : experiment::load_preset(a.preset);
  if (!a.algorithms.empty()) experiment::restrict_algorithms(config, a.algorithms);
  if (a.instances != 0) experiment::set_instance_count(config, a.instances);
  if (a.first_seed) experiment::set_first_seed(config, *a.first_seed);
  return config;
}

int list_presets() {
  for (const auto& name : experiment::preset_names()) {
    const auto config = experiment::load_preset(name);
    const std::size_t runs = config.scenarios.size() * config.s2.size() * config.uavs.size() *
                             config.algorithms.size() * config.seeds.size();
    std::cout << fmt::format("{:<12} {:>6} runs  {}\n", name, runs, config.description);
  }
  return 0;
}

int run(const ExperimentArgs& a) {
  if (a.list_presets) return list_presets();
  experiment::RunnerOptions options;
  options.jobs = a.jobs;
  options.resume = a.resume;
  if (!a.shard.empty()) {
    options.shard = experiment::parse_shard(a.shard);
  } else if (auto slurm = experiment::shard_from_slurm(
                 [](const char* n) -> const char* { return std::getenv(n); })) {
    options.shard = *slurm;
    std::cerr << fmt::format("hullinspect: shard {} (from the Slurm job array)\n", slurm->text());
  }
  io::OutputSet outputs;
  outputs.add_input(a.config, "config");
  if (!a.dry_run) outputs.add_output_dir(a.out, "out");
  outputs.check();
  const experiment::ExperimentPlan plan(load(a));  // validates every cell before anything runs
  const auto& config = plan.config();
  int in_shard = 0;
  for (int p = 0; p < static_cast<int>(plan.runs().size()); ++p)
    in_shard += options.shard.contains(p);
  if (a.dry_run) {
    const auto count = [](const auto& items, std::string_view noun) {
      return plural(static_cast<long long>(items.size()), noun);
    };
    std::cout << fmt::format("{}: {} × {} s2 × {} × {} = {}; × {} ({}) = {} ({} in shard {})\n",
                             config.name, count(config.scenarios, "scenario"), config.s2.size(),
                             count(config.uavs, "fleet size"),
                             count(config.algorithms, "algorithm"), count(plan.cells(), "cell"),
                             count(config.seeds, "instance"), seeds_text(config.seeds),
                             count(plan.runs(), "run"), in_shard, options.shard.text());
    return 0;
  }
  if (a.out.empty()) throw ParameterError("out", "name the results directory with --out DIR");

  ProgressReporter reporter(::isatty(STDERR_FILENO) == 1);
  options.on_progress = [&](const experiment::Progress& p) { reporter.update(p); };
  options.on_note = [](const std::string& note) { std::cerr << "hullinspect: " << note << "\n"; };
  const auto summary = experiment::run_experiment(plan, a.out, options);
  reporter.finish();
  std::cout << fmt::format(
      "{}: {} of shard {} in {} ({} now in {:.1f} s, {:.1f} missions/s, {}, {} resumed)\n",
      config.name, plural(summary.total, "run"), options.shard.text(), a.out,
      plural(summary.ran, "run"), summary.seconds,
      summary.seconds > 0 ? summary.ran / summary.seconds : 0.0, plural(summary.jobs, "job"),
      summary.resumed);
  if (options.shard.whole()) {
    std::cout << fmt::format("next: hullinspect report {} --out {}/report\n", a.out, a.out);
  } else {
    std::cout << "next: when every shard has finished, hullinspect merge DIR... --out MERGED\n";
  }
  return 0;
}

}  // namespace

void add_experiment_command(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<ExperimentArgs>();
  CLI::App* cmd = app.add_subcommand(
      "experiment", "Run an experiment (the cartesian product of a config's lists) in parallel");
  cmd->footer(
      "Results in DIR: runs.csv (one row per mission), curves.csv (mean/std of c(t), m(t) per "
      "cell), samples.csv, timings.csv, manifest.json. See docs/experiments.md.\n"
      "Example: hullinspect experiment --preset paper-quick --out results/quick");
  std::string presets;
  for (const auto& name : experiment::preset_names())
    presets += (presets.empty() ? "" : ", ") + name;
  cmd->add_option("--preset", args->preset, "Built-in experiment: " + presets)->type_name("NAME");
  cmd->add_option("--config", args->config, "Experiment config (YAML, see docs/experiments.md)")
      ->type_name("FILE");
  cmd->add_option("--out,-o", args->out, "Results directory (new or empty, or with --resume)")
      ->type_name("DIR");
  cmd->add_option("--jobs,-j", args->jobs, "Worker threads (0: every core)")
      ->check(integer_in(0, experiment::kMaxJobs))
      ->capture_default_str();
  cmd->add_flag("--resume", args->resume,
                "Continue the experiment in DIR: keep finished runs, run the missing ones");
  cmd->add_option("--shard", args->shard,
                  "Run only shard K of N (runs whose position mod N is K-1); default from "
                  "SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT when set")
      ->type_name("K/N");
  cmd->add_option("--algorithms", args->algorithms,
                  "Run only these algorithms of the config (labels, comma-separated)")
      ->delimiter(',')
      ->type_name("LIST");
  cmd->add_option("--instances", args->instances, "Override the config's instances with seeds 1..N")
      ->check(integer_in(1, 1'000'000))
      ->type_name("N");
  cmd->add_option("--first-seed", args->first_seed,
                  "Run consecutive seeds from this one instead (as many as --instances or the "
                  "config has): seeds held out from tuning");
  cmd->add_flag("--dry-run", args->dry_run, "Validate and count cells and runs; run nothing");
  cmd->add_flag("--list-presets", args->list_presets, "List the built-in presets and exit");
  cmd->callback([args, &action] { action = [args] { return run(*args); }; });
}

void add_experiment_commands(CLI::App& app, CommandAction& action) {
  add_experiment_command(app, action);
  add_merge_command(app, action);
  add_report_command(app, action);
}

}  // namespace hullinspect::cli
