#pragma once
// Segment division of Part-TSP (model.md §5.3, paper IV-A.2): in each strip of s_z rows, a column is
// targeted when a cell of the strip in that column belongs to R_k and holds the target value in
// M^k; a segment is a maximal run of targeted columns, flown along the strip's flight row.

#include <cstdint>
#include <vector>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/planners/part_tsp_local_map.hpp"

namespace hullinspect::planners::part_tsp {

struct StripSegment {
  int strip = 0;    ///< strip index j in the layout of the plane
  int row = 0;      ///< its flight row y_j
  int x_left = 0;   ///< first targeted column
  int x_right = 0;  ///< last targeted column (inclusive)
  /// A point visit (no-fly zones only): the allowed position from which the targeted cells of
  /// column x_left = x_right are seen; kNoCell for a segment flown along its row.
  grid::Cell point = grid::kNoCell;
  friend bool operator==(const StripSegment&, const StripSegment&) = default;
};

/// Fills `out` (cleared first) with UAV k's segments on plane z for `value`, strips bottom to top,
/// segments left to right. Reads only the column counts of `maps` (no rescan of the region).
void divide_into_segments(const LocalMaps& maps, int k, int z, std::int8_t value,
                          std::vector<StripSegment>& out);

/// The same division with no-fly positions (docs/model.md): a run of targeted columns is split
/// wherever its flight-row position is not allowed; a targeted cell that no segment of its strip
/// sees (its column is outside every segment's footprint reach) becomes a point visit at
/// `distances.viewpoint()` (a zero-length segment; cells with no viewpoint are left out). Fills
/// `out` and the matching flown `ends` (segment_ends with `trim`, or the point twice).
void divide_around_no_fly(const LocalMaps& maps, int k, int z, std::int8_t value, int trim,
                          grid::DistanceService& distances, std::vector<StripSegment>& out,
                          std::vector<std::pair<grid::Cell, grid::Cell>>& ends);

/// Whether some column between x_from and x_to (inclusive, either order) of the segment's strip
/// still holds a cell of R_k with `value`.
bool has_targets(const LocalMaps& maps, int k, int z, std::int8_t value,
                 const StripSegment& segment, int x_from, int x_to);

/// The two ends the UAV flies between: (x_left, row) and (x_right, row); with `trim` > 0 (the
/// footprint half-width) both ends move inwards by `trim`, meeting in the middle when the segment
/// is at most 2·trim + 1 wide — the footprint still sweeps every targeted column.
std::pair<grid::Cell, grid::Cell> segment_ends(const StripSegment& segment, int trim);

}  // namespace hullinspect::planners::part_tsp
