#pragma once
// The local maps M^k of Part-TSP (model.md §5.3): UAV k knows only its region R_k, and only from
// its own readings (no communication). Regions are disjoint, so all the M^k live in one grid where
// a cell holds the value of its owner's map.
//
// Alongside the values it keeps, per UAV, h (cells with M^k = 2), the number of unknown cells and,
// for the strip layout of each plane, how many cells of R_k in each strip column hold 0 or 2. Those
// counts are what segment division reads, so a plan never rescans the region.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/sim/types.hpp"
#include "hullinspect/world/mission_params.hpp"

namespace hullinspect::planners::part_tsp {

/// Horizontal strips of s rows from the bottom of the grid (strip j = rows [j·s, (j+1)·s)), each
/// flown along its flight row y_j = min(j·s + (s − 1)/2, b − 1).
struct StripLayout {
  int s = 1;
  int height = 0;
  int strips() const { return (height + s - 1) / s; }
  int strip_of(int y) const { return y / s; }
  int first_row(int j) const { return j * s; }
  int last_row(int j) const { return (j + 1) * s < height ? (j + 1) * s - 1 : height - 1; }
  int flight_row(int j) const {
    const int centre = j * s + world::footprint_half(s);
    return centre < height ? centre : height - 1;
  }
};

/// What one UAV's readings of one step meant for its local map.
struct LocalEvents {
  bool detection =
      false;  ///< it saw, from z = 2, a corroded cell of R_k it had not seen from z = 2
  bool inspection = false;  ///< a cell of R_k turned to 3 in M^k
};

class LocalMaps {
 public:
  /// `owner` is the partition (A, eq. 3). With `use_prior` the maps start with the prior's 2s
  /// (Part-TSP); without, every hull cell starts at 0 (Part-TSP₀).
  LocalMaps(const grid::Grid<std::int16_t>& owner, const grid::Grid<std::int8_t>& prior,
            bool use_prior, int uavs, int s1, int s2);

  /// No-fly zones (docs/model.md): a cell no z = 2 footprint reaches can never reach its final
  /// state and reads 1 in M^k from now on (nothing is left to do there). A prior cell (2) no z = 1
  /// footprint reaches reads 0: if it is clean it must still be seen from z = 2; once seen
  /// corroded, ingest() writes it off. `reach` holds world::kReachZ1/Z2 bits.
  void write_off(const grid::Grid<std::uint8_t>& reach);

  /// Applies UAV k's readings of one step to M^k (the model.md §3 table, cells of R_k only).
  LocalEvents ingest(int k, std::span<const sim::Reading> readings);

  /// Work sharing (docs/part-tsp.md, "Work sharing"): the hull cells `cells` (flat
  /// indices, owned by any UAV) join R_to with what their owner's map knew of them — the value and
  /// whether they were seen from z = 2 — or, with `forget`, with what every UAV knew at the start
  /// (the value before any reading: the prior's 2s, the no-fly write-offs; not seen). Counts move
  /// with them; R_to's column range grows when it has to (O(strips · width) then, never a rescan
  /// of the grid).
  void hand_over(std::span<const int> cells, int to, bool forget);

  int uavs() const { return static_cast<int>(regions_.size()); }
  int width() const { return owner_.width(); }
  int height() const { return owner_.height(); }
  /// M^{A(i)} at cell i; −1 off the hull.
  std::int8_t value(int index) const { return values_[index]; }
  std::int8_t value(grid::Cell c) const { return values_[c]; }
  const grid::Grid<std::int8_t>& values() const { return values_; }
  int owner(int index) const { return owner_[index]; }
  int owner(grid::Cell c) const { return owner_[c]; }

  /// h: cells of R_k with M^k = 2.
  int corrosion_to_inspect(int k) const { return region(k).twos; }
  /// Cells of R_k with M^k = 0.
  int unknown_cells(int k) const { return region(k).zeros; }
  int region_cells(int k) const { return region(k).cells; }
  /// Columns spanned by R_k: [x_begin, x_end).
  int x_begin(int k) const { return region(k).x_begin; }
  int x_end(int k) const { return region(k).x_begin + region(k).width; }

  /// The strip layout of plane z (strips of s_z rows).
  const StripLayout& layout(int z) const { return layouts_[static_cast<std::size_t>(z - 1)]; }
  /// Cells of R_k in column x of strip j (plane z's layout) whose M^k is `value` (0 or 2).
  int column_count(int k, int z, std::int8_t value, int strip, int x) const;
  /// Cells of R_k in column x of strip j (plane z's layout), whatever their value.
  int column_cells(int k, int z, int strip, int x) const;

 private:
  struct Region {
    int x_begin = 0;
    int width = 0;
    int cells = 0;
    int twos = 0;
    int zeros = 0;
    /// Per plane: (strip · width + x − x_begin) · 3 + {0: cells, 1: value 0, 2: value 2}.
    std::array<std::vector<int>, 2> columns;
  };
  const Region& region(int k) const { return regions_[static_cast<std::size_t>(k)]; }
  std::size_t column_slot(const Region& r, int z, int x, int y) const;
  void set_value(int index, std::int8_t value);
  /// Adds (+1) or removes (−1) cell `index` with value `value` to/from the counts of `r`.
  void count(Region& r, int index, std::int8_t value, int delta);
  /// Widens r's column range to [x_begin, x_end), keeping its counts.
  void widen(Region& r, int x_begin, int x_end);

  grid::Grid<std::int16_t> owner_;
  grid::Grid<std::int8_t> values_;
  grid::Grid<std::uint8_t> seen_from_z2_;            // UAV A(i) has seen cell i from z = 2
  grid::Grid<std::int8_t> start_values_;             // values_ before any reading
  const grid::Grid<std::uint8_t>* reach_ = nullptr;  // set by write_off()
  std::array<StripLayout, 2> layouts_;
  std::vector<Region> regions_;
};

}  // namespace hullinspect::planners::part_tsp
