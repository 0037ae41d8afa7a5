#pragma once
// Internal to DarpPartitioner: the buffers and the per-iteration steps of DARP (model.md §5.1).
//
// Representation. Hull cells are numbered 0..N-1 in (y, x) order, so the per-cell steps never scan
// non-hull cells; the distance transforms run on a copy of the grid padded with a ring of blocked
// cells, so they need no bounds checks. The evaluation matrix of UAV r is kept as
// logarithms, E_r[j] = log(evaluation): DARP's multiplicative updates (fairness multiplier,
// connectivity correction, random factor) become additions, nothing overflows however long a run
// is, and the argmin of the assignment is unchanged. A multiplier that scales every entry of E_r
// (the fairness multiplier) is kept as one number per UAV, fair_[r], and added at assignment.
//
// Every buffer is allocated in the constructor; assign(), check_connectivity(), update() and the
// remember_*() calls allocate nothing. Per iteration: the assignment and the random factors touch
// each of the n·N entries once (vectorised); components are labelled from the same-owner runs of
// every row (Θ(N) plus union-find over the runs); a split region's connectivity correction (two
// BFS over the hull) is rebuilt only when the region changed since it was last built, otherwise it
// is re-applied from a cache.

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "hullinspect/partition/darp_partitioner.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/random.hpp"

namespace hullinspect::partition::detail {

/// Natural logarithm of x > 0 from +, −, ×, ÷ only, so results are bit-identical on every platform
/// (std::log is not guaranteed to be correctly rounded). Accurate to a few ulp.
double portable_log(double x);

class DarpWorkspace {
 public:
  /// `start_index`: flat grid index of each UAV's start (hull cells, distinct). `weights`: per-cell
  /// weights on the grid, or nullptr for weight 1 everywhere. `desired`: desired weight per UAV.
  DarpWorkspace(const world::HullMask& hull, std::span<const int> start_index,
                const grid::Grid<double>* weights, std::span<const double> desired,
                const DarpOptions& options, std::uint64_t seed);

  /// No-fly zones and neighbour flights (docs/model.md): re-initialises the evaluation matrices
  /// from the distance service's shortest flights over `allowed` positions, each neighbour flight
  /// taking its steps in `flights`, from each start instead of the BFS through hull cells; a cell
  /// no flight reaches gets the largest finite distance + 1.
  void use_allowed_distances(const grid::Grid<std::uint8_t>& allowed,
                             std::span<const int> start_index, const grid::EdgeSteps& flights);

  /// A grid that closes on itself (`flights.seam`, darp_seam.cpp): the two end cells of every
  /// linked row are neighbours in the connectivity check, the corrections' distances and the
  /// repair, so a region may cross the seam. Nothing without a seam.
  void link_seam(const grid::EdgeSteps& flights);

  /// Every hull cell to the UAV of lowest evaluation (ties: lowest UAV id); start cells stay with
  /// their UAV. Updates the region sizes and weights and the same-owner runs of every row.
  void assign();
  /// Labels the 4-connected components of every region (from the runs of assign()).
  void check_connectivity();
  bool all_connected() const { return split_count_ == 0; }
  bool split(int uav) const { return split_[static_cast<std::size_t>(uav)] != 0; }
  /// Total weight of the cells outside their owner's start component (0 when all connected).
  double stray_weight() const { return stray_weight_; }
  /// Largest |region weight − desired weight| over the UAVs.
  double discrepancy() const;
  /// Applies the fairness multipliers (for the tolerance `tolerance_weight`), the connectivity
  /// corrections of split regions and the random factors to the evaluation matrices.
  void update(double tolerance_weight);

  /// Keeps the current assignment if it is connected and better balanced than the best kept one.
  void remember_connected(double discrepancy);
  /// Keeps the current assignment if its score — discrepancy plus stray weight, a bound on the
  /// discrepancy after repair_best_balanced() — is lower than every earlier one's.
  void remember_balanced(double score);
  bool has_connected() const { return best_connected_discrepancy_ >= 0; }
  double best_connected_discrepancy() const { return best_connected_discrepancy_; }
  /// Turns the best-scoring assignment into a connected one: every cell outside its owner's start
  /// component goes to the region it is nearest to (BFS through such cells from the start
  /// components). Returns the discrepancy of the result, which becomes the best connected one if it
  /// is better balanced.
  double repair_best_balanced();

  enum class Which { kCurrent, kBestConnected };
  /// Writes an assignment as the owner grid (non-hull cells untouched) and its region totals.
  void export_assignment(Which which, grid::Grid<std::int16_t>& owner,
                         std::vector<int>& region_cells, std::vector<double>& region_weight) const;

 private:
  void add_noise_and_compare(int uav);
  void update_fairness(double tolerance_weight);
  void build_correction(int uav);
  /// Multi-source BFS through hull cells from the cells queue_[0, sources) into the padded grid
  /// `dist`; returns the largest distance reached.
  int hull_bfs(std::vector<int>& dist, int sources);
  int find_root(int run);
  /// Joins the same-owner runs that meet across the seam (part of check_connectivity()).
  void join_across_seam();
  void totals_of(const std::vector<std::int32_t>& owner, std::vector<int>& cells,
                 std::vector<double>& weight) const;

  int n_ = 0;
  int cell_count_ = 0;
  DarpOptions options_;
  world::RandomStream rng_;
  std::vector<int> cell_flat_;           // hull cell j → flat grid index
  std::vector<int> cell_x_;              // hull cell j → x
  std::vector<std::uint8_t> row_start_;  // 1 where the west neighbour is not a hull cell
  std::vector<int> row_first_;           // first hull cell of each row (height + 1 entries)
  std::vector<int> neighbours_;          // 4 per cell, −1 where there is no hull neighbour
  std::vector<int> start_;               // start cell (hull index) per UAV
  std::vector<double> weight_;           // per cell; empty = unweighted
  std::vector<double> desired_;          // per UAV
  double total_weight_ = 0;

  std::vector<float> eval_;               // n × N log-evaluations, UAV-major
  std::vector<double> fair_;              // per UAV: accumulated log fairness multiplier
  std::vector<double> gain_;              // per UAV: current fairness gain
  std::vector<int> last_sign_;            // per UAV: sign of its last non-zero share error
  std::vector<float> best_value_;         // N: assignment scratch
  std::vector<std::int32_t> next_owner_;  // N: assignment scratch
  std::vector<std::int32_t> owner_;       // N: current assignment (n = nobody yet)
  std::vector<int> region_cells_;
  std::vector<double> region_weight_;
  std::vector<std::uint8_t> changed_;  // per UAV (+ sentinel): region changed since last correction

  // Components by runs: maximal same-owner horizontal runs of hull cells, joined by union-find
  // with the overlapping same-owner runs of the row below.
  std::vector<int> run_of_;           // N: run of each cell
  std::vector<int> run_x0_, run_x1_;  // per run: x range
  std::vector<std::int32_t> run_owner_;
  std::vector<int> run_parent_;
  std::vector<int> run_root_;       // per run: its component's root run
  std::vector<double> run_weight_;  // per run: its weight
  std::vector<int> row_runs_;       // first run of each row (height + 1 entries)
  int run_count_ = 0;
  std::vector<int> components_;      // per UAV
  std::vector<int> start_root_;      // per UAV: root run of the start's component
  std::vector<std::uint8_t> split_;  // per UAV: region has more than one component
  int split_count_ = 0;
  double stray_weight_ = 0;  // weight outside the start components

  std::vector<int> queue_;               // N: hull cell indices
  int padded_width_ = 0;                 // grid width + 2
  std::vector<int> pad_of_;              // hull cell j → index in the padded grid
  std::vector<int> padded_blank_;        // padded grid: unreached on hull cells, blocked elsewhere
  std::vector<int> pad_queue_;           // N: padded indices
  std::vector<int> pad_near_;            // padded: distance to the start's component
  std::vector<int> pad_far_;             // padded: distance to the other components
  std::vector<int> mark_;                // N: repair marks
  std::unique_ptr<float[]> correction_;  // n × N cached log-corrections (written before read)
  // The seam (link_seam()): per linked row whose two ends are hull cells, the hull indices of its
  // first and last cells; per padded position, its partner across the seam or −1 (empty: no seam).
  std::vector<std::array<int, 2>> seam_ends_;
  std::vector<int> seam_partner_;

  std::vector<float> noise_;       // N log random factors, read at a random rotation
  std::vector<int> noise_offset_;  // per UAV, drawn in update()
  bool noise_pending_ = false;

  std::vector<std::int32_t> best_connected_;
  double best_connected_discrepancy_ = -1;
  std::vector<std::int32_t> best_balanced_;
  double best_balanced_score_ = -1;
};

}  // namespace hullinspect::partition::detail
