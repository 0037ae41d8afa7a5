#pragma once
// The Partitioner stage: divides the hull among the UAVs (the assignment matrix A, eq. 3).

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/core/options.hpp"
#include "hullinspect/core/registry.hpp"
#include "hullinspect/grid/flight_steps.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::partition {

struct PartitionRequest {
  const world::HullMask* hull = nullptr;
  std::vector<grid::Cell> starts;  ///< one hull cell per UAV (already snapped), distinct
  /// Optional weight per cell (size of the grid; > 0 on hull cells). Empty = every cell weighs 1.
  grid::Grid<double> weights;
  /// Optional share per UAV (positive, any scale). Empty = equal shares.
  std::vector<double> shares;
  std::uint64_t seed = 0;
  /// No-fly zones only: the positions UAVs can fly (1) — DARP's initial distances are then the
  /// shortest flights over them (docs/model.md). Empty = none (BFS through hull cells).
  grid::Grid<std::uint8_t> allowed;
  /// No-fly zones only: per hull cell, the flight component that sees it, -1 none
  /// (world::Reachability::seen_from). When the starts lie in several flight components, the
  /// partition is made per component (partition/flight_split.hpp). Empty = one flight space.
  grid::Grid<int> seen_from;
  /// Unrolled hulls only: the steps of each neighbour flight (grid/flight_steps.hpp), which DARP's
  /// initial distances then add up. Empty = every flight one step.
  grid::EdgeSteps flights;
};

struct Partition {
  /// A: -1 not hull, k = cell assigned to UAV k.
  grid::Grid<std::int16_t> owner;
  std::vector<int> region_cells;       ///< cells per UAV
  std::vector<double> region_weight;   ///< weight per UAV (= cells when unweighted)
  std::vector<double> desired_weight;  ///< what each UAV should get
  int iterations = 0;                  ///< partitioner iterations (0 for one-shot partitioners)
  bool converged = true;               ///< met its balance goal with connected regions
  double tolerance = 0;  ///< balance tolerance reached (weight units; cells if unweighted)
  double seconds = 0;
  std::vector<std::string> warnings;  ///< e.g. "returned the best connected partition found"
  /// Set by partition_with_fallback() (partition/fallback.hpp): the partitioner that produced this
  /// partition after the requested one (DARP) did not converge; empty otherwise.
  std::string fallback;
};

class Partitioner {
 public:
  virtual ~Partitioner() = default;
  /// Returns a partition in which every hull cell has one owner and every region is 4-connected.
  /// Throws Error when none can be produced.
  virtual Partition partition(const PartitionRequest& request) const = 0;
};

using PartitionerInfo = RegistryEntry<Partitioner>;
using PartitionerRegistry = Registry<Partitioner>;

/// Every partitioner by name ("darp", "stripes"); add your own with partitioners().add(…).
PartitionerRegistry& partitioners();
/// A snapshot of partitioners().entries().
std::vector<PartitionerInfo> partitioner_registry();
/// Throws ParameterError("partitioner", …) for an unknown name.
std::unique_ptr<Partitioner> make_partitioner(std::string_view name, const OptionMap& options = {});
/// The effective options of a partitioner (validated, defaults filled in).
OptionMap resolve_partitioner_options(std::string_view name, const OptionMap& options = {});
/// The default partitioner's name.
inline constexpr std::string_view kDefaultPartitioner = "darp";

}  // namespace hullinspect::partition
