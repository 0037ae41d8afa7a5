#pragma once
// Sweep-Inspect (docs/sweep-inspect.md): a planner of this project, beyond the paper. Each UAV
// sweeps its region (a piece of one boustrophedon over the hull's column bands, of equal expected
// work; a column slab or a DARP region where pieces or slabs are not connected) at the detection
// plane z = 2 in bands of s2 rows or columns (band_sweep.hpp; so it observes at the rate bound's s2
// new cells per step), descends once a detected corroded cell of the shared map lies abreast of it
// (no longer ahead on its leg), inspects the detected cells near that point at z = 1 (nearest
// first), climbs back and resumes its sweep where it left it, or plans it anew from there when
// that is the shorter flight. A UAV whose sweep is done helps: it takes the nearest unclaimed
// detected, uninspected cell (at z = 1), else the far end of the sweep that would end last
// (a sweep's tail), else the nearest unknown cell (at z = 2), which also finishes the region of a
// failed UAV. Communication: the shared map M and the failed flags (as Coop-Frontier), plus each
// helper's current target (its claim).

#include <memory>
#include <optional>
#include <vector>

#include "hullinspect/planners/band_partition.hpp"
#include "hullinspect/planners/band_sweep.hpp"
#include "hullinspect/planners/flight_distances.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/planners/prior_tour_split.hpp"
#include "hullinspect/planners/sweep_approach.hpp"
#include "hullinspect/planners/waypoint_follower.hpp"

namespace hullinspect::planners {

struct SweepInspectOptions {
  /// The regions' last fallback (a piece of the band partition or a column slab not
  /// 4-connected): this partitioner, its options and seed.
  std::string partitioner{partition::kDefaultPartitioner};
  OptionMap partitioner_options;
  std::uint64_t partition_seed = 0;
  bool prior_weights = true;     ///< partition weighted by the expected work per cell
  bool prior_statistics = true;  ///< those weights use the scenario's p_TP, p_FP
  bool prior_first = true;       ///< first tour the prior's cells of the region at z = 1
  /// Drop the prior (stop its tours) when fewer than this fraction of its cells are corroded:
  /// at the start when the scenario's statistics say so, else once its first cells are seen
  /// (0: never).
  double prior_trust = 0.8;
  /// The cells of a corrosion zone whose expected corroded fraction (of what the sweep will find:
  /// without the prior's toured cells) exceeds this are swept at z = 1 in bands of s1 (1: never).
  double low_sweep_above = 0.1;
  /// The sweep's bands: "rows" (s2 rows from the grid's bottom, flown along the hull),
  /// "columns" (s2 columns, flown up and down the hull's height) or "auto" (per region and
  /// re-plan, the shorter flight; the band partition's z = 2 sweeps fly its columns).
  std::string strips = "auto";
  /// With batteries, a sweeping UAV ends its sortie where that is cheapest along its sweep
  /// (sweep_returns.hpp) instead of where the sortie layer would send it home.
  bool planned_returns = true;
};

class SweepInspectPlanner final : public Planner {
 public:
  explicit SweepInspectPlanner(SweepInspectOptions options) : options_(std::move(options)) {}
  void start(const PlannerContext& context) override;
  void decide(const sim::PlannerView& view, std::span<sim::Action> actions) override;
  void returns(const sim::PlannerView& view, std::vector<int>& uavs) override;
  bool idle(const sim::PlannerView& view) const override;
  const partition::Partition* partition() const override { return partition_.get(); }
  void annotate(AnnotationSink& sink) const override;

 private:
  enum class Mode { kPrior, kSweep, kInspect, kReturn, kHelp, kDone, kFailed };
  struct Uav {
    Mode mode = Mode::kPrior;
    WaypointFollower sweep;
    grid::Cell resume{-1, -1};        // where the sweep was left for an inspection
    grid::Cell target{-1, -1};        // the position it flies to (inspect / help)
    int target_cell = -1;             // the cell that target serves (its claim)
    bool sweep_planned = false;       // its sweep was planned (it left the prior's cells once)
    Mode after_prior = Mode::kSweep;  // where to go on when prior cells handed over are done
    bool replan = false;              // its cells were re-split (a failure): plan strips anew
    BandAxis axis = BandAxis::kRows;  // the direction of its sweep's bands
    bool low = false;                 // its sweep is flown at z = 1 (low-sweep-above)
    bool other_part = false;          // its cells of the other plane are swept after these
    std::size_t approach_rest = 0;    // waypoints after its sweep's approach (0: none left)
    grid::Cell viewpoint{-1, -1};     // where it flies at z = 1 (inspection_viewpoint)
    // Its prior cells in the planned order (empty: plan one), tour[tour_next]
    // the first not yet seen when last looked; `repaired` when it was planned over more than
    // kReplannedTourCells cells, so that it is repaired, not planned anew, until re-assigned.
    std::vector<int> tour;
    std::size_t tour_next = 0;
    bool repaired = false;
  };
  // The state machine (sweep_inspect_modes.cpp). A UAV's mode, and how it leaves it:
  //   kPrior   tours its prior cells at z = 1 → kSweep (first time), or back to what it left
  //            for prior cells handed over (kReturn, kHelp)
  //   kSweep   flies its bands (z = 2, or z = 1 in dense columns) → kInspect (descended for a
  //            detection abreast), kHelp (its sweep is done)
  //   kInspect inspects the detections around its descent at z = 1 → kReturn (climbed), kSweep
  //            (the sweep planned from here starts at z = 1)
  //   kReturn  flies back to where it rejoins its sweep → kSweep, kInspect
  //   kHelp    takes the nearest unclaimed work anywhere → kSweep (a sweep's tail taken, or cells
  //            of a failure's re-split), kDone (nothing left)
  //   kDone    hovers → kHelp (work may appear)
  //   kFailed  (failed)
  // Any of kSweep, kHelp, kDone → kPrior when prior cells of a failed UAV are handed to it.
  /// UAV k's action this step: the functions of its modes, in turn, until one acts.
  sim::Action decide_uav(int k, const sim::UavState& u, const sim::PlannerView& view);
  /// Any of kSweep, kHelp, kDone → kPrior when `prior` (the UAV's) holds cells handed over.
  static void take_handed_prior(Uav& p, const sim::UavState& u, const std::vector<int>& prior);
  /// Each mode's step: the action, or nullopt when the UAV moved to a mode that now decides.
  std::optional<sim::Action> sweep_mode(int k, const sim::UavState& u,
                                        const sim::PlannerView& view);
  std::optional<sim::Action> return_mode(int k, const sim::UavState& u,
                                         const sim::PlannerView& view);
  std::optional<sim::Action> inspect_mode(int k, const sim::UavState& u,
                                          const sim::PlannerView& view);
  std::optional<sim::Action> help_mode(int k, const sim::UavState& u, const sim::PlannerView& view);
  /// kSweep at z = 2: descend for a detection abreast, else on along the sweep.
  std::optional<sim::Action> sweep_at_z2(int k, const sim::UavState& u,
                                         const sim::PlannerView& view);
  /// Mode kPrior: UAV k's next move on its tour of the prior's cells at z = 1; nullopt when the
  /// tour is done and the UAV has moved on to its sweep (or back to what it left).
  std::optional<sim::Action> prior_tour_step(int k, const sim::UavState& u,
                                             const sim::PlannerView& view);
  /// Whether a detected cell is abreast of UAV k sweeping at `pos` (or beyond the leg it
  /// flies), so that it descends now.
  bool detection_abreast(int k, grid::Cell pos, const sim::PlannerView& view) const;
  /// Mode kHelp: UAV k's next move towards the nearest unclaimed work anywhere; nullopt when it
  /// took a sweep's tail (now kSweep).
  std::optional<sim::Action> help_step(int k, const sim::UavState& u, const sim::PlannerView& view);
  /// Removes from owner_ UAV k's cells that are observed already (a sweep planned then skips them),
  /// but for the detections in columns swept at z = 1, which that sweep is to inspect, and those
  /// a re-split gave it (resplit_detection_), which its sweep is to pass abreast of.
  void drop_observed(int k, const sim::PlannerView& view);
  /// UAV k's next move along its sweep (skipping bands seen already); nullopt when this part is
  /// done: its other part planned (still kSweep), or, the sweep over, now kHelp.
  std::optional<sim::Action> follow_sweep(int k, const sim::UavState& u,
                                          const sim::PlannerView& view);
  /// Plans the part of UAV k's cells on the other plane, when the current part's sweep is done.
  void next_part(int k, const sim::UavState& u);
  /// Nearest pending detected cell to `pos` within Chebyshev radius `radius` of `around` (any
  /// radius when radius < 0), not claimed by another UAV; −1 if none.
  int nearest_pending(int k, grid::Cell pos, grid::Cell around, int radius,
                      const sim::PlannerView& view) const;
  /// The position UAV k at z = 1 flies to next, `held` while its footprint
  /// still takes in work, else the one taking in the most work cells within Chebyshev `radius` of
  /// `around` per step of flight; kNoCell when no work is left there. `cell` is set to a work
  /// cell it takes in (the UAV's claim), or −1.
  grid::Cell inspection_viewpoint(int k, grid::Cell pos, grid::Cell around, int radius,
                                  grid::Cell held, int& cell, const sim::PlannerView& view);
  /// Work beside an inspected cell: cell (x, y) is unobserved, has an inspected 4-neighbour, and
  /// UAV k may look at it from z = 1 (reachable, not claimed by another UAV).
  bool cluster_edge(int k, int x, int y, const sim::PlannerView& view) const;
  /// Nearest unknown hull cell (M = 0) not claimed by another UAV; −1 if none.
  int nearest_unknown(int k, grid::Cell pos, const sim::PlannerView& view) const;
  bool claimed_by_other(int k, int cell) const;
  /// Whether UAV k may inspect detected cell i: seen from z = 1 by some position it can reach,
  /// not claimed by another UAV, not left_to_low_sweep.
  bool may_inspect(int k, int i) const;
  /// After a re-split, whether detected cell i is in another UAV's share of
  /// the dense columns while that UAV is still sweeping them at z = 1.
  bool left_to_low_sweep(int k, int i) const;
  /// low-sweep-above: marks the columns of the corrosion zones (one zone when the statistics are
  /// unknown) whose cells the sweep expects corroded more often than low-sweep-above.
  void find_dense_columns(const PlannerContext& context);
  /// The band partition: the pieces of one boustrophedon over the hull's bands, of equal expected
  /// work (the request's weights, dense columns at z = 1), and band_start_ for their sweeps;
  /// null when a piece is not 4-connected.
  /// The band partition's cuts moved a few rows at a time while that makes the
  /// latest planned end earlier (or keeps it and spreads the ends less).
  /// `cuts` are `pieces`' (rows.balanced_cuts()).
  partition::Partition balance_flights(const BandPieces& rows, std::vector<std::size_t> cuts,
                                       partition::Partition pieces, const PlannerContext& context);
  /// The steps of UAV k's sweep as planned from `from` over owner_ (both parts; flight_steps).
  double planned_sweep_steps(int k, grid::Cell from);
  /// The flight of UAV k from `from` through `waypoints`, leg by leg as flight() gives it.
  double flight_steps(int k, grid::Cell from, const std::vector<grid::Cell>& waypoints);
  /// UAV k's flight from a to b: its distance service's (Manhattan without no-fly zones), or
  /// Manhattan where that finds no path.
  int flight(int k, grid::Cell a, grid::Cell b);
  std::shared_ptr<const partition::Partition> band_partition(
      const partition::PartitionRequest& request, const PlannerContext& context);
  bool prior_distrusted() const {
    if (prior_dropped_) return true;
    const int seen = prior_true_ + prior_false_;
    return options_.prior_trust > 0 && seen >= kPriorCheckCells &&
           prior_true_ < options_.prior_trust * seen;
  }
  /// The strips of UAV k's region flown from `from` (its cells in owner_): over its cells in dense
  /// columns at z = 1 (bands of s1), over the others at z = 2 (bands of s2); when it has both, the
  /// part whose first waypoint is nearer first (Uav::low says which, Uav::other_part that the
  /// other follows).
  std::vector<grid::Cell> sweep_from(int k, grid::Cell from);
  /// The strips over UAV k's cells in dense (`low`) or other columns, flown from `from`; sets
  /// Uav::low to `low`. `approach` as strips_from's.
  std::vector<grid::Cell> part_strips(int k, bool low, grid::Cell from, bool approach = true);
  /// The strips over the cells where `owner` is k flown from `from`: boustrophedon_from's, as
  /// two blocks of columns where low_blocks finds that shorter.
  std::vector<grid::Cell> strips_from(const grid::Grid<std::int16_t>& owner, int k, grid::Cell from,
                                      bool approach = true);
  /// One boustrophedon over the cells where `owner` is k (bands of s2, or of s1 when Uav::low)
  /// flown from `from`, from the nearer end; led by an edge approach unless `approach` is false.
  std::vector<grid::Cell> boustrophedon_from(const grid::Grid<std::int16_t>& owner, int k,
                                             grid::Cell from, bool approach);
  /// After a failure's re-split, `waypoints` (UAV k's sweep of its cells in
  /// `owner` from `from`) become two blocks of columns where that is a shorter flight, if the
  /// sweep is at z = 1 (Uav::low).
  void low_blocks(const grid::Grid<std::int16_t>& owner, int k, grid::Cell from,
                  std::vector<grid::Cell>& waypoints);
  /// At a failure: every cell not yet observed is split anew among the working
  /// UAVs in column slabs, left to right in the order of their positions, so that their predicted
  /// ends — the prior's cells left to visit, the flight to the slab, the slab — are as early as
  /// can be; each then sweeps its slab's strips from where it is.
  void resplit(const sim::PlannerView& view);
  /// UAV k at `pos`, its prior tour done, takes part of the longest prior tour left;
  /// true if it took cells.
  bool take_prior_share(int k, grid::Cell pos);
  /// Splits `cells` between UAV a at pa and UAV b at pb (PriorTourSplitter::split, with the
  /// cells each may reach at z = 1): a takes the first `first` of them (the order is left in
  /// `cells`).
  PriorTourSplitter::Split split_tours(int a, grid::Cell pa, int b, grid::Cell pb,
                                       std::vector<int>& cells);
  /// At the start and after a failure's prior cells were handed over: neighbours (by
  /// x of `at`, working UAVs only when `view` is given) re-split their prior cells so that their
  /// tours from `at` end together (kBalancePasses passes over the neighbour pairs).
  void balance_prior_tours(std::span<const grid::Cell> at, const sim::PlannerView* view = nullptr);
  static constexpr int kBalancePasses = 3;
  /// The next cell of UAV k's planned z = 1 tour over its prior cells `cells`
  /// that is still to be inspected; the tour is planned from `from` when it has none, and a tour
  /// planned short (over at most kReplannedTourCells cells) is repaired from `from`
  /// (repair_open_tour) where cells left it.
  int next_of_tour(int k, grid::Cell from, std::span<const int> cells,
                   const sim::PlannerView& view);
  /// Puts the cells of UAV p's short tour still to inspect, in its order, in tour_points_, and
  /// the nodes next to those dropped (and the start) in tour_touched_; false when they are not
  /// its `cells` prior cells left (plan the tour anew).
  bool repair_tour(const Uav& p, std::size_t cells, const sim::PlannerView& view);
  /// A tour planned over more cells only drops its cells as they are seen: even the repair's
  /// linear work per change would grow with the square of the hull. Neither is planned anew on
  /// every cell seen, which costs the cube of the tour's cells.
  static constexpr std::size_t kReplannedTourCells = 400;
  /// UAV k's prior cells were re-assigned: its next tour is planned anew.
  void forget_tour(int k) {
    uavs_[static_cast<std::size_t>(k)].tour.clear();
    uavs_[static_cast<std::size_t>(k)].tour_next = 0;
    uavs_[static_cast<std::size_t>(k)].repaired = false;
  }
  /// UAV j (state u), its sweep done, takes the tail of the remaining sweep of the
  /// working UAV of its flight part that would end last, if that ends the two at least s2 steps
  /// sooner; true if it took one.
  bool take_sweep_tail(int j, const sim::UavState& u, const sim::PlannerView& view);
  /// Hands the prior cells of failed UAVs to the working UAV nearest to each.
  /// True when some cells were handed over.
  bool hand_over_prior(const sim::PlannerView& view);
  /// Drops the follower's waypoints of UAV k's band legs ahead of `pos` whose
  /// footprints would see no unobserved cell.
  void skip_seen_bands(Uav& p, grid::Cell pos, const sim::PlannerView& view) const;
  /// Work left at cell i for a sweep at z = 1 (`low`) or z = 2: sweep_work, or a detection a
  /// re-split gave to a share (resplit_detection_), which a band passing abreast inspects.
  bool sweep_work_left(const sim::PlannerView& view, int i, bool low) const;
  /// Whether a flight along one band line from `a` to `b` would see an unobserved cell (at z = 1,
  /// `low`: with the s1 footprint, or a detected cell to inspect).
  bool leg_sees_unobserved(grid::Cell a, grid::Cell b, bool low,
                           const sim::PlannerView& view) const;
  /// UAV k, its inspection done at `pos`, plans its sweep from `pos` when that is
  /// shorter than flying back to Uav::resume and on; true (and Uav::resume = pos) if it did.
  bool replan_after_inspection(int k, grid::Cell pos, const sim::PlannerView& view);
  /// Nearest position to `pos` whose footprint of half-width h holds `c` (its clamp into the
  /// footprint square); with no-fly zones, when that is not flyable by UAV k, the viewpoint of c
  /// in UAV k's service (kNoCell when its part of the flight space has none).
  grid::Cell reach_position(int k, grid::Cell pos, grid::Cell c, int h) const;
  /// Whether UAV k can ever see cell i from z = 1 (bit kReachZ1) / z = 2 (kReachZ2): some flyable
  /// position does, and, when no-fly zones cut the flight space into parts, one of k's part.
  bool reachable(int k, int i, std::uint8_t bit) const;
  /// The move from `pos` one step along UAV k's service's shortest flight to `to`.
  sim::Action step(int k, grid::Cell pos, grid::Cell to) const;

  /// The prior is judged (prior-trust) once this many of its cells have been seen.
  static constexpr int kPriorCheckCells = 10;
  /// In the band partition, the inspections expected at a cell the sweep detects (its weight's
  /// excess over 1) count this many times, a prior cell's toured first kPriorTourWeight times:
  /// the tours are re-split among neighbours after the partition (balance_prior_tours), so a
  /// piece that the partition shrank for its whole tour would end its sweep early.
  static constexpr double kInspectionWeight = 2.0;
  static constexpr double kPriorTourWeight = 0.25;
  /// Dense columns spanning at most this many bands of s1 (among other cells of a region) are
  /// swept at z = 2 with the rest: each z = 1 band is a whole pass of the hull's height.
  static constexpr int kLowSweepMinBands = 2;
  /// Passes of the flight balancing over the band partition's cuts.
  static constexpr int kBalanceRounds = 10;

  SweepInspectOptions options_;
  std::shared_ptr<const partition::Partition> partition_;
  /// The band partition's grid: per column, the first column of its band (empty: each region's own
  /// bands).
  std::vector<int> band_start_;
  std::vector<Uav> uavs_;
  std::vector<int> pending_;  // detected (seen at z = 2), not yet inspected cells, flat indices
  std::vector<int> hull_cells_;
  std::vector<std::vector<int>> prior_;  // per UAV: the prior's cells of its region still M = 2
  // Whose strips each cell is in: the partition until a failure re-splits the cells not yet
  // observed among the working UAVs (-1: nobody's).
  grid::Grid<std::int16_t> owner_;
  std::vector<char> handed_over_;  // per UAV: its failure was handled
  bool resplit_ = false;           // owner_ is a failure's re-split
  // Per cell: detected and not yet inspected at a failure's re-split, which gave it to the share
  // whose sweep is to pass abreast of it (its finder may be the failed UAV).
  grid::Grid<std::uint8_t> resplit_detection_;
  std::vector<char> dense_column_;       // per column: swept at z = 1 (empty: none is)
  grid::Grid<std::int16_t> part_owner_;  // owner_ restricted to one part of a UAV's cells
  SweepScratch sweep_scratch_;           // scratch of approach_and_sweep
  // While the band partition's cuts are balanced: the columns that hold the cells of the piece
  // being planned, so that its sweep reads only those ({0, -1}: every column).
  std::pair<int, int> piece_columns_{0, -1};
  PriorTourSplitter tours_;                // the prior tours' estimates and splits
  std::vector<grid::Cell> tour_points_;    // scratch of next_of_tour
  std::vector<std::size_t> tour_touched_;  // scratch of next_of_tour: nodes where a tour changed
  std::vector<int> split_cells_;
  std::vector<grid::Cell> return_route_;  // scratch of returns(): a UAV's route ahead
  std::vector<int> tail_walk_;            // scratch of split_sweep_tail: walk lengths along a sweep
  // Scratch of inspection_viewpoint: work cells per position of the window around the inspection,
  // and their 2D prefix sums (one more row and column).
  std::vector<int> view_work_;
  std::vector<int> view_work_sums_;
  std::vector<double> split_load_;                         // per UAV, in cells
  std::vector<std::pair<int, grid::Cell>> split_helpers_;  // (UAV, where its work ends)
  /// The planning estimates of the split: a sweep sees about this fraction of s2 new cells per
  /// step (its inspections included), a visit of a prior cell
  /// costs about this many steps.
  static constexpr double kSweepRate = 0.6;
  static constexpr double kPriorVisitSteps = 1.5;
  grid::DistanceService own_distances_;
  grid::DistanceService* distances_ = nullptr;
  FlightDistances flights_;
  std::vector<grid::DistanceService*> uav_distances_;  // per UAV: flights_.of(k)
  const grid::Grid<std::uint8_t>* reach_ = nullptr;    // null: no no-fly zones, all reachable
  std::vector<grid::Cell> positions_;                  // the UAVs' positions at this decision
  /// Scratch of nearest_unknown: the distances from the deciding UAV's position, one search per
  /// call (a distance() per candidate would search from every candidate cell).
  mutable grid::Grid<int> from_here_;
  int width_ = 0;
  grid::Cell hull_cell(int index) const { return {index % width_, index / width_}; }
  bool prior_dropped_ = false;  // the statistics say the prior is not worth a tour
  int prior_true_ = 0;          // prior cells found corroded so far (fleet-wide)
  int prior_false_ = 0;         // prior cells found clean so far
  // The footprint's sides on planes 1 and 2 (MissionParams::footprint) and their half-sides
  // (MissionParams::half_side).
  int s1_ = 5;
  int s2_ = 7;
  int h1_ = 2;
  int h2_ = 3;
  int radius_ = 7;
};

}  // namespace hullinspect::planners
