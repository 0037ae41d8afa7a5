#pragma once
// Mission-state vocabulary: map values (eq. 2), UAV state, actions and sensor readings.

#include <cstdint>
#include <string_view>

#include "hullinspect/grid/cell.hpp"
#include "hullinspect/grid/flight_steps.hpp"

namespace hullinspect::sim {

/// Values of the mission map M (eq. 2).
inline constexpr std::int8_t kNotHull = -1;
inline constexpr std::int8_t kUnknown = 0;
inline constexpr std::int8_t kClean = 1;  ///< non-corroded, seen at z = 1 or 2
inline constexpr std::int8_t kCorrosionSeen =
    2;                                        ///< corroded, expected (prior) or detected at z = 2
inline constexpr std::int8_t kInspected = 3;  ///< corroded, inspected at z = 1

/// Bits of the `seen` flags the simulator keeps per cell.
inline constexpr std::uint8_t kSeenAtZ2 = 1;
inline constexpr std::uint8_t kSeenAtZ1 = 2;

enum class Action : std::uint8_t {
  kHover,
  kNorth,  ///< y + 1 (up)
  kSouth,  ///< y − 1 (down)
  kEast,   ///< x + 1 (towards the bow)
  kWest,   ///< x − 1 (towards the stern)
  kChangePlane,
};

std::string_view to_string(Action a);

/// The move that takes `from` one step towards `to` under the project's fixed Manhattan rule:
/// first along x, then along y. kHover when from == to.
Action step_towards(grid::Cell from, grid::Cell to);
/// `c` moved by `a` (unchanged for hover and plane change).
grid::Cell moved(grid::Cell c, Action a);
/// `c` moved by `a` on a width × height grid with the neighbour flights `steps`: across a linked
/// seam (grid::neighbour) west of column 0 is column W − 1 and east of W − 1 is column 0. A move
/// off the grid elsewhere is returned off the grid, for the caller to refuse.
grid::Cell moved(grid::Cell c, Action a, int width, int height, const grid::EdgeSteps& steps);
/// The move from `from` to `next`, one of its 4-neighbours on the grid (grid::neighbour): across
/// the seam, towards the column at the other end of the row; otherwise step_towards(from, next).
Action move_to_neighbour(grid::Cell from, grid::Cell next);

struct UavState {
  grid::Cell pos;
  int z = 2;             ///< plane: 1 close-up, 2 detection (the departure plane during a change)
  int transit_left = 0;  ///< steps left in a plane change; 0 = on a plane
  /// Set from the start of the UAV's failure step on (docs/model.md, "Failures"): its actions are
  /// ignored, it stays where it is (in transit forever if it failed while changing plane) and
  /// senses nothing. Planners use it only as far as their communication model allows.
  bool failed = false;
  /// Steps left flying between the UAV's launch site and the hull (docs/model.md, "Launch sites"):
  /// on the ground, taking off, flying out to its start cell, or flying home and landing after the
  /// hull is complete. Like a plane change, the UAV cannot act and senses nothing meanwhile.
  int away_left = 0;
  /// Steps left of a neighbour flight longer than one step (docs/model.md "Neighbour flights"):
  /// the UAV is already at its new position and, like a plane change, cannot act and senses
  /// nothing until the flight's steps are flown.
  int flight_left = 0;
  /// False while on the ground at a launch site: before the first take-off, swapping a battery,
  /// and after the last landing. Always true without launch sites (the paper's model).
  bool airborne = true;
  /// Steps of flight left on the battery (docs/model.md, "Batteries and sorties"); −1 unlimited.
  int battery_left = -1;
  /// True while the UAV cannot act: changing plane, flying to a distant neighbour, or away at its
  /// launch site.
  bool in_transit() const { return transit_left > 0 || away_left > 0 || flight_left > 0; }
};

/// Event bits of a reading.
inline constexpr std::uint8_t kEventFirstSeen = 1;   ///< first observation of the cell by anyone
inline constexpr std::uint8_t kEventDetection = 2;   ///< first sight of this corroded cell at z = 2
inline constexpr std::uint8_t kEventInspection = 4;  ///< the cell turned to 3
inline constexpr std::uint8_t kEventRedundant = 8;   ///< nothing new: M unchanged and no detection

/// One hull cell in one UAV's footprint: what that UAV's camera reported.
struct Reading {
  int index = 0;            ///< flat cell index
  std::int8_t value = 0;    ///< 1 clean, 2 corrosion seen from z = 2, 3 corrosion seen at z = 1
  std::uint8_t events = 0;  ///< kEvent* bits
};

}  // namespace hullinspect::sim
