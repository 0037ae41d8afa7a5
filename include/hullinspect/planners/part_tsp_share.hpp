#pragma once
// Work sharing in Part-TSP (docs/part-tsp.md, "Work sharing"; the paper's future work 2):
// what a UAV that is done takes over from another. Only at hand-over events, never per step: the
// remaining cells of a region are collected by a scan of that region's column range, the split
// reads two distance fields.

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/planners/part_tsp_local_map.hpp"
#include "hullinspect/planners/part_tsp_path.hpp"

namespace hullinspect::planners::part_tsp {

/// UAV k's remaining work in M^k in the prior-aware partition's units (prior_weights.hpp: one z = 2
/// pass over a cell weighs 1, a z = 1 inspection s2/s1): unknown cells + s2/s1 · cells to inspect.
double remaining_work(const LocalMaps& maps, int k);

/// The cells of R_k whose value in M^k is 0 or 2 (flat indices, increasing), into `out`; with
/// `every_cell`, all the cells of R_k.
void region_cells(const LocalMaps& maps, int k, bool every_cell, std::vector<int>& out);

/// The helper's piece of an owner's remaining cells: cells ordered by how much nearer they are to
/// the helper than to the owner (d_helper − d_owner, then index). With T the owner's estimated
/// steps left and d the helper's flight to the nearest remaining cell, a fraction
/// f = (T − d) / (2T) of the work makes both end together if the helper works as fast as the owner;
/// the helper takes the shortest prefix whose work reaches f · W. Nothing (false) when the owner
/// would save less than `min_steps` (f · T). `d_helper`/`d_owner`: flight distances from the two
/// UAVs' positions to every cell. `order` is scratch.
bool helper_piece(const LocalMaps& maps, std::span<const int> cells,
                  const grid::Grid<int>& d_helper, const grid::Grid<int>& d_owner,
                  double owner_steps, double min_steps,
                  std::vector<std::pair<long long, int>>& order, std::vector<int>& piece);

/// The tail of the owner's plan for the helper: `visits` are the visits the owner still has to fly
/// (the first one possibly begun, ending at `waypoints[0]`... as SegmentPath::remaining() lists
/// them: `waypoints` = the exit of a begun first visit, then entry and exit of each other one).
/// Returns the index m of the first visit handed over: the one that minimises the later of the two
/// ends — the owner flying visits [0, m), the helper flying from its position to visit m's entry
/// and on to the end (Manhattan estimates) — or −1 when no m ≥ 1 saves `min_steps` against the
/// owner flying everything.
int plan_tail(std::span<const PlannedVisit> visits, std::span<const grid::Cell> waypoints,
              grid::Cell owner_pos, grid::Cell helper_pos, double min_steps);

/// Appends to `out` the cells of R_k that `visit` (planned on plane z for `value`) targets: in its
/// strip and columns, or for a point visit those in the footprint around its point.
void visit_cells(const LocalMaps& maps, int k, int z, std::int8_t value, const PlannedVisit& visit,
                 std::vector<int>& out);

/// Steps of a flight from `pos` through `waypoints` in order (Manhattan: an estimate).
int plan_length(grid::Cell pos, std::span<const grid::Cell> waypoints);

/// Flight distances from `from` to every cell into `out` (sized already): Manhattan without
/// no-fly positions, else the service's field.
void flight_field(grid::DistanceService& distances, grid::Cell from, grid::Grid<int>& out);

}  // namespace hullinspect::planners::part_tsp
