#pragma once
// The one distance service every planner uses (docs/model.md, "No-fly zones"): shortest
// 4-connected path lengths over the positions a UAV may occupy. Built once per mission from the
// allowed-position mask. Without no-fly positions or long neighbour flights every answer is the
// Manhattan one, computed in O(1) without any search, so results are identical to a world without
// the service.
//
// Distances between *cells* (targets such as a corroded cell behind a mooring line) follow one
// rule: a path's interior must be allowed, its two end cells need not be. For two allowed
// positions this is exactly the shortest flight.
//
// Neighbour flights (grid/flight_steps.hpp): on a hull where some neighbours are several steps
// apart, a path's length is the sum of its flights' steps, searched by Dijkstra over those small
// integer weights. Without such a table nothing changes.
//
// Not thread-safe: one service per mission (the fields are cached per source).

#include <cstdint>
#include <span>
#include <vector>

#include "hullinspect/grid/distance.hpp"
#include "hullinspect/grid/flight_steps.hpp"
#include "hullinspect/grid/grid.hpp"

namespace hullinspect::grid {

class DistanceService {
 public:
  /// How many single-source fields are kept (least recently used is replaced).
  static constexpr int kDefaultCachedFields = 64;

  DistanceService() = default;
  /// Every position of a width × height grid allowed: Manhattan distances.
  DistanceService(int width, int height);
  /// `allowed[i] != 0`: a UAV may be at cell i.
  explicit DistanceService(Grid<std::uint8_t> allowed, int cached_fields = kDefaultCachedFields);
  /// As above, with neighbour flights of `steps` steps (an empty table: every flight one step).
  DistanceService(Grid<std::uint8_t> allowed, EdgeSteps steps,
                  int cached_fields = kDefaultCachedFields);

  int width() const { return allowed_.width(); }
  int height() const { return allowed_.height(); }
  /// True when some position is not allowed (distances then come from searches).
  bool has_no_fly() const { return no_fly_count_ > 0; }
  int no_fly_count() const { return no_fly_count_; }
  /// True when some neighbour flight takes more than one step.
  bool has_long_flights() const { return !steps_.empty(); }
  /// True when distances are not the Manhattan ones (no-fly positions or long flights), so that
  /// they come from searches (field()) rather than grid::manhattan().
  bool searched() const { return has_no_fly() || has_long_flights(); }
  /// The steps of every neighbour flight (empty: one step each).
  const EdgeSteps& flight_table() const { return steps_; }
  /// Steps of the flight from `a` to its 4-neighbour `b`.
  int flight(Cell a, Cell b) const { return steps_.between(a, b); }
  bool allowed(Cell c) const { return allowed_.contains(c) && allowed_[c] != 0; }
  bool allowed(int index) const { return allowed_[index] != 0; }
  /// 1 where a UAV may be.
  const Grid<std::uint8_t>& allowed_mask() const { return allowed_; }

  /// Shortest path length from a to b (interior allowed), in steps; Manhattan when not searched();
  /// kUnreachable when no such path exists.
  int distance(Cell a, Cell b);

  /// field[i] = distance(source, cell i) for every cell. The reference stays valid until the next
  /// call of field(), distance(), next_step() or append_path() on this service.
  const Grid<int>& field(Cell source);

  /// The allowed 4-neighbour of allowed position `from` to fly to on a shortest path towards `to`:
  /// along x towards `to` first, then along y (the project's Manhattan rule, sim::step_towards),
  /// then any other neighbour in the order east, west, north, south — the first that lies on a
  /// shortest path. Never a position that is not allowed: when `to` is not allowed and adjacent, or
  /// `from == to`, or `to` cannot be reached, returns `from`.
  Cell next_step(Cell from, Cell to);

  /// Appends the positions after `from` up to `to` along next_step(); stops early (without
  /// appending `to`) when `to` is not allowed or cannot be reached. Returns true when `to` was
  /// appended (or from == to).
  bool append_path(Cell from, Cell to, std::vector<Cell>& out);

  /// distance(source, targets[t]) into out[t] for every t: from `source`'s cached field when it
  /// has one, else by a search from `source` that stops once every target is settled and caches
  /// nothing, so its cost follows how far the targets are rather than the grid's size, and it
  /// evicts no cached field.
  void distances_to(Cell source, std::span<const Cell> targets, std::span<int> out);

  /// Distance from every cell to the nearest cell with sources != 0 (same path rule). O(cells) and
  /// allocation-free once `out` has the grid's size; kUnreachable everywhere without sources.
  void distances_from(const Grid<std::uint8_t>& sources, Grid<int>& out);

  /// Where to fly to see cell `c` with a footprint of side 2·half + 1: `c` itself when allowed,
  /// else the allowed position within Chebyshev radius `half` of `c` nearest to it (Manhattan),
  /// ties lowest (y, x); kNoCell when there is none.
  Cell viewpoint(Cell c, int half);

  /// Single-source searches run so far (for tests and benchmarks).
  long long searches() const { return searches_; }

 private:
  struct Slot {
    int source = -1;
    long long last_used = 0;
    Grid<int> field;
  };
  const Grid<int>& cached_field(int source);
  /// Breadth-first search from the seeds in `scratch_.queue[0, seeds)` (already 0 in `out`):
  /// expands allowed cells and the seeds, gives every other cell its distance as a path end.
  void search(Grid<int>& out, std::size_t seeds);
  /// The same search with neighbour flights' steps as weights (Dial's bucket queue).
  void search_weighted(Grid<int>& out, std::size_t seeds);

  Grid<std::uint8_t> allowed_;
  int no_fly_count_ = 0;
  std::vector<Slot> slots_;
  std::vector<int> slot_of_;  // per cell: its slot, or -1
  long long clock_ = 0;
  long long searches_ = 0;
  BfsScratch scratch_;
  EdgeSteps steps_;
  int longest_flight_ = 1;
  std::vector<std::vector<int>> buckets_;  // search_weighted's queue: distance mod (longest + 1)
  // distances_to(): distances reached (kUnreachable elsewhere), which cells it set, and per cell
  // 1 for a target not settled yet, 2 for one settled; all restored before it returns.
  Grid<int> near_;
  std::vector<int> touched_;
  std::vector<std::uint8_t> target_state_;
  std::vector<int> targets_marked_;
};

/// Exact Manhattan (4-neighbour, obstacle-free) distance from every cell to the nearest cell with
/// sources != 0, by one forward and one backward raster pass: O(cells), no allocation once `out`
/// has the right size. With no source every cell gets kUnreachable.
void manhattan_distance_transform(const Grid<std::uint8_t>& sources, Grid<int>& out);

}  // namespace hullinspect::grid
