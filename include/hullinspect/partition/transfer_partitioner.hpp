#pragma once
// The `transfer` partitioner (docs/partition.md): the geodesic Voronoi partition grown from the
// start cells, then balanced exactly by moving boundary cells from over-full to under-full regions
// along paths of adjacent regions, each move keeping both regions 4-connected. Deterministic (the
// seed only orders ties in retries); an alternative to DARP for large fleets and hulls.

#include <vector>

#include "hullinspect/core/parameters.hpp"
#include "hullinspect/partition/partitioner.hpp"

namespace hullinspect::partition {

struct TransferOptions {
  /// Largest number of transfer rounds (one round moves cells along one path of adjacent regions
  /// from an over-full to an under-full region). Reaching it returns the partition so far, which is
  /// connected, with a warning (converged = false).
  int round_limit = 100'000;
  /// Attempts: when the transfers get stuck (a region walled in by regions that cannot give up a
  /// cell without splitting), start again from the Voronoi partition with cells of equal distance
  /// ordered by a seeded random jitter instead of by index. The best-balanced attempt is returned.
  int attempts = 8;
  /// Regrowth attempts (n > 1): after attempt 0 and again after the seeded attempts, the regions
  /// grown with per-region head starts (offsets on the distances, then competing fronts with
  /// per-region speeds, then after attempt 0 also offsets with adaptive step bounds) adjusted until
  /// their sizes are near the targets, then balanced by the same transfers. For start sets whose Voronoi cells are pockets far below their share (starts a few
  /// cells apart). They draw nothing from the seeded stream.
  bool regrow = true;
  /// Grow the regions from spread virtual starts (the model's default start cells for n UAVs)
  /// instead of the UAVs' own starts, for UAVs that launch close together: a region then need not
  /// hold its UAV's start, and the UAV flies to it first (the mission counts that transit). UAVs
  /// are matched to virtual starts in (x, y) order of their real starts.
  bool spread_starts = false;
};

/// The declared options ("round-limit"; defaults from TransferOptions{}).
const Params<TransferOptions>& transfer_params();

class TransferPartitioner final : public Partitioner {
 public:
  explicit TransferPartitioner(TransferOptions options = {}) : options_(options) {}
  /// Same requests and input errors as DarpPartitioner (starts snapped to the hull, distinct;
  /// weights; shares; no-fly positions through `allowed`). Unweighted, every region gets its
  /// desired cell count rounded to a whole number (largest remainders), so |cells − desired| < 1;
  /// weighted, the goal is every region within one heaviest cell of its desired weight. Regions are
  /// always 4-connected and hold their start cells; when the goal is missed (no movable boundary
  /// cell on any path, or round_limit reached) the partition is returned with a warning and
  /// converged = false. Throws Error when a hull cell is not 4-connected to any start cell.
  Partition partition(const PartitionRequest& request) const override;
  const TransferOptions& options() const { return options_; }

 private:
  TransferOptions options_;
};

}  // namespace hullinspect::partition
