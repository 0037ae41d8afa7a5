#pragma once
// Part-TSP and Part-TSP₀ (model.md §5.3, paper Section IV-A): a partition at t = 0, a local map per
// UAV fed only by its own readings, the plane-change FSM of Fig. 3, and plans that cover (z = 2) or
// inspect (z = 1) the UAV's region segment by segment in the order of a segment TSP.
// docs/part-tsp.md describes the behaviour, the path and transit rules and the options.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hullinspect/planners/flight_distances.hpp"
#include "hullinspect/planners/part_tsp_fsm.hpp"
#include "hullinspect/planners/part_tsp_local_map.hpp"
#include "hullinspect/planners/part_tsp_path.hpp"
#include "hullinspect/planners/part_tsp_segments.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/tsp/segment_tsp.hpp"

namespace hullinspect::planners {

struct PartTspOptions {
  bool use_prior = true;  ///< false: Part-TSP₀ (local maps start without the prior's 2s)
  bool oracle = false;    ///< oracle-part-tsp: the local maps start from the truth C, not C'

  int r1 = 2;  ///< steps since the last detection before descending
  int r2 = 0;  ///< steps since the last inspection (or arrival at z = 1) before ascending
  std::string tsp_solver{tsp::kDefaultTspSolver};  ///< segment-TSP solver by name ("exact")
  OptionMap tsp_solver_options;
  /// A plan over more segments is ordered by the local search (the `heuristic` solver with the
  /// exact solver's first-tour settings) instead of `tsp_solver`, without a proof: every solve's
  /// work stays bounded as regions grow. The paper preset's largest plan has 28 segments, so
  /// its plans are unchanged. 0 = no cap.
  int tsp_max_segments = 30;
  std::string partitioner{partition::kDefaultPartitioner};  ///< by name
  OptionMap partitioner_options;
  std::uint64_t partition_seed = 0;  ///< seed of the partitioner (not of the instance)
  // Refinements beyond the paper, off by default (their measured effect: docs/part-tsp.md).
  bool skip_resolved = false;  ///< drop plan segments whose targets are all resolved already
  bool trim_ends = false;      ///< fly segments between ends pulled in by the footprint half-width
  // Beyond the paper, off by default (prior_weights.hpp, docs/model.md §5.5).
  bool prior_weights = false;    ///< partition weighted by the expected work per cell
  bool prior_statistics = true;  ///< those weights use the scenario's p_TP, p_FP
  /// A UAV that is done takes over a failed UAV's region, else part of the most loaded UAV's
  /// remaining work (docs/part-tsp.md, "Work sharing").
  bool share_work = false;
};

class PartTspPlanner final : public Planner {
 public:
  /// Builds the TSP solver by name unless one is given (tests inject their own).
  explicit PartTspPlanner(PartTspOptions options, std::unique_ptr<tsp::TspSolver> solver = nullptr);

  void start(const PlannerContext& context) override;
  void decide(const sim::PlannerView& view, std::span<sim::Action> actions) override;
  sim::PlannerStats stats() const override { return stats_; }
  bool sees_truth() const override { return options_.oracle; }
  const partition::Partition* partition() const override { return partition_.get(); }
  /// Every working UAV is done (nothing left in its local map): without communication nobody takes
  /// over a failed UAV's region, so the mission ends there (docs/failures.md). With share-work, not
  /// while a failed UAV's region has work left that a working UAV can fly to.
  bool idle(const sim::PlannerView& view) const override;
  /// Per UAV: mode (cover-z2, inspect-z1, cover-z1, descending, ascending, done, failed), the next
  /// waypoint and the waypoints still ahead.
  void annotate(AnnotationSink& sink) const override;

  const PartTspOptions& options() const { return options_; }
  // Read-only views for tests and tools (valid after start()).
  const part_tsp::LocalMaps& local_maps() const { return *maps_; }
  const part_tsp::SegmentPath& path(int k) const { return uav(k).path; }
  std::string_view mode(int k) const { return uav(k).mode; }
  /// Plane and target value of UAV k's current plan.
  int plan_plane(int k) const { return uav(k).plan_z; }
  std::int8_t plan_value(int k) const { return uav(k).plan_value; }
  /// Plans UAV k has made so far.
  int plans_made(int k) const { return uav(k).plans; }
  /// share-work: regions of failed UAVs taken over, and pieces taken from working UAVs.
  int failed_regions_taken() const { return failed_regions_taken_; }
  int pieces_taken() const { return pieces_taken_; }

 private:
  struct UavState {
    int plane = 0;               // plane it was last seen on, out of transit (0: not seen yet)
    int last_detection = 0;      // t of its last detection (0: mission start)
    int last_inspection = 0;     // t of its last inspection
    int last_arrival_z1 = 0;     // t of its last arrival at z = 1
    int plan_z = 0;              // plane the current plan was made for
    std::int8_t plan_value = 0;  // target value of the current plan
    int plans = 0;
    std::string_view mode = part_tsp::kModeCoverZ2;
    part_tsp::SegmentPath path;
  };
  const UavState& uav(int k) const { return uavs_[static_cast<std::size_t>(k)]; }
  sim::Action decide_uav(int k, const sim::UavState& u, int time);
  void make_plan(int k, grid::Cell pos, int z);
  void skip_resolved(int k, grid::Cell pos);
  /// share-work: done UAV j takes over work; true when it got some (both UAVs then replan).
  bool take_over(int j, const sim::PlannerView& view);
  /// share-work: a failed UAV's region with work left in a flight part where a UAV still works.
  bool failed_work_reachable(const sim::PlannerView& view) const;

  PartTspOptions options_;
  std::unique_ptr<tsp::TspSolver> solver_;
  std::unique_ptr<tsp::TspSolver> large_solver_;  // plans over more than tsp_max_segments
  std::shared_ptr<const partition::Partition> partition_;
  std::unique_ptr<part_tsp::LocalMaps> maps_;
  std::vector<UavState> uavs_;
  sim::PlannerStats stats_;
  grid::DistanceService* distances_ = nullptr;  // the mission's, or own_distances_
  grid::DistanceService own_distances_;
  FlightDistances flights_;  // per UAV: the service of its flight component (distances_ if one)
  // Scratch reused by every plan.
  std::vector<part_tsp::StripSegment> segments_;
  std::vector<std::pair<grid::Cell, grid::Cell>> ends_;
  std::vector<tsp::Visit> order_;
  tsp::SegmentTsp problem_;
  // share-work (reserved at start; used only at hand-over events).
  std::vector<int> part_of_;  // per UAV: its flight part (0 when the flight space is one)
  std::vector<int> declined_;  // [j·n + k]: k's cells left when j declined a piece of k (−1: never)
  std::vector<int> share_cells_;
  std::vector<int> share_piece_;
  std::vector<std::pair<long long, int>> share_order_;
  grid::Grid<int> helper_field_;
  grid::Grid<int> owner_field_;
  int failed_regions_taken_ = 0;
  int pieces_taken_ = 0;
};

}  // namespace hullinspect::planners
