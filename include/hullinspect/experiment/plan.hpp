#pragma once
// An experiment expanded: the cells of the cartesian product scenario × s2 × uavs × algorithm, and
// one run per cell and seed, each with a stable id. Every algorithm gets the same seeds (paired).

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "hullinspect/experiment/config.hpp"
#include "hullinspect/planners/mission_spec.hpp"

namespace hullinspect::experiment {

/// One cell of the product (indices into the config's lists).
struct Cell {
  int scenario = 0;
  int s2 = 0;
  int uavs = 0;
  int algorithm = 0;
  std::string canonical;  ///< every parameter of the cell as one canonical string
  std::string id;         ///< stable_id(canonical)
};

struct RunKey {
  int cell = 0;
  int seed_index = 0;
  std::uint64_t seed = 0;
  std::string id;  ///< stable_id(cell canonical string + seed)
};

class ExperimentPlan {
 public:
  /// Expands `config` and validates every cell (planners::validate) before anything runs. A bad
  /// value or planner option throws InputError naming the config file and the line of the value.
  /// A config without a hull mask (read back from a manifest) is expanded without validation.
  explicit ExperimentPlan(ExperimentConfig config);

  const ExperimentConfig& config() const { return config_; }
  /// Cells in canonical order: scenario, then s2, then uavs, then algorithm (config order).
  const std::vector<Cell>& cells() const { return cells_; }
  /// Runs in canonical order: by cell, then by seed.
  const std::vector<RunKey>& runs() const { return runs_; }
  /// Canonical position of a run id, or -1.
  int run_position(const std::string& id) const;
  /// The mission of one run.
  planners::MissionSpec mission(const RunKey& run) const;
  planners::MissionSpec mission(const Cell& cell, std::uint64_t seed) const;

 private:
  void validate_cell(const Cell& cell) const;

  ExperimentConfig config_;
  std::vector<Cell> cells_;
  std::vector<RunKey> runs_;
  std::unordered_map<std::string, int> position_;
};

}  // namespace hullinspect::experiment
