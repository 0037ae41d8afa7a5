// Fuzz target: the YAML experiment config parser and the plan it validates (docs/experiments.md).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/config.hpp"
#include "hullinspect/experiment/plan.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    // Relative hull paths resolve against a directory that does not exist.
    auto config = hullinspect::experiment::parse_config(text, "fuzz.yaml", "/nonexistent-fuzz-dir");
    // Every cell is validated by constructing its planner (planners::validate); the checks are
    // the same for every cell, so a few cells cover them and a fuzzed "uavs: [1, …, 500]" does
    // not make one input cost thousands of planner constructions (a run only costs its id).
    const std::size_t cells =
        config.s2.size() * config.uavs.size() * config.algorithms.size() * config.scenarios.size();
    if (cells <= 64 && cells * config.seeds.size() <= 4096) {
      const hullinspect::experiment::ExperimentPlan plan(std::move(config));
      (void)plan.runs().size();
    }
  } catch (const hullinspect::Error&) {
  }
  return 0;
}
