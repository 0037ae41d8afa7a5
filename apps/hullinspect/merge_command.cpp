// hullinspect merge: combine the results directories of an experiment's shards.

#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "experiment_commands.hpp"
#include "hullinspect/core/plural.hpp"
#include "hullinspect/experiment/merge.hpp"
#include "hullinspect/files/output_set.hpp"

namespace hullinspect::cli {

namespace {

struct MergeArgs {
  std::vector<std::string> inputs;
  std::string out;
};

int run(const MergeArgs& a) {
  std::vector<std::filesystem::path> inputs(a.inputs.begin(), a.inputs.end());
  io::OutputSet outputs;
  for (const auto& dir : a.inputs) outputs.add_input(dir, "input directory");
  outputs.add_output_dir(a.out, "out");
  outputs.check();
  const auto summary = experiment::merge_results(inputs, a.out);
  for (const auto& note : summary.notes) std::cerr << "hullinspect: " << note << "\n";
  std::cout << fmt::format("merged {} into {}: {}",
                           plural(summary.inputs, "directory", "directories"), a.out,
                           plural(summary.runs, "run"));
  if (summary.duplicates > 0) {
    std::cout << fmt::format(", {} dropped", plural(summary.duplicates, "duplicate"));
  }
  std::cout << "\n";
  if (summary.missing > 0) {
    std::cerr << fmt::format(
        "hullinspect: {} of the experiment {} in none of the inputs (the merge is partial; "
        "finish the missing shards with --resume and merge again)\n",
        plural(summary.missing, "run"), summary.missing == 1 ? "is" : "are");
    return 3;
  }
  return 0;
}

}  // namespace

void add_merge_command(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<MergeArgs>();
  CLI::App* cmd = app.add_subcommand("merge", "Combine the results of an experiment's shards");
  cmd->footer(
      "The merged directory equals an unsharded run's (same runs.csv, samples.csv, curves.csv).\n"
      "Exit status: 0 complete, 3 some runs missing (partial merge), 2 invalid input.\n"
      "Example: hullinspect merge results/shard-* --out results/merged");
  cmd->add_option("dirs", args->inputs, "Results directories of the shards")
      ->required()
      ->type_name("DIR...");
  cmd->add_option("--out,-o", args->out, "New (or empty) directory for the merged results")
      ->required()
      ->type_name("DIR");
  cmd->callback([args, &action] { action = [args] { return run(*args); }; });
}

}  // namespace hullinspect::cli
