#pragma once
// No-fly positions (docs/model.md, "No-fly zones"): grid positions where no UAV may be, on either
// plane, and what follows from them before a mission starts — which positions the fleet can fly
// to and which hull cells can still be inspected (z = 1) or detected (z = 2).

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/grid/grid.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::world {

/// A rectangle of cells, corners inclusive (x0 ≤ x1, y0 ≤ y1 after normalisation).
struct CellBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// 1 at every no-fly position of a grid the size of the hull.
using NoFlyMask = grid::Grid<std::uint8_t>;

/// Builds the mask for `hull`: the no-fly cells of `file` (any hull-mask format, read with
/// load_cell_map; its size must equal the hull's) plus every box (clipped to nothing: a box must
/// lie inside the grid). Empty `file` = no file. Throws InputError naming the file for a size
/// mismatch and ParameterError("no-fly-box", …) for a box outside the grid.
NoFlyMask make_no_fly_mask(const HullMask& hull, const std::filesystem::path& file,
                           std::span<const CellBox> boxes);

/// Parses "X0,Y0,X1,Y1" (cells, inclusive). Throws ParameterError(option, …).
CellBox parse_cell_box(const std::string& text, const std::string& option);

/// Everything a mission derives from its no-fly positions before it starts.
struct Reachability {
  /// Positions a UAV can be at: not no-fly and 4-connected over such positions to a start (the
  /// neighbours of grid::neighbour: across the seam of a grid that closes on itself too).
  grid::Grid<std::uint8_t> flyable;
  /// Per cell: kReachZ2 | kReachZ1 bits (hull cells only; 0 elsewhere).
  grid::Grid<std::uint8_t> reach;
  int unreachable_z1 = 0;  ///< hull cells no flyable z = 1 footprint contains (never inspectable)
  int unreachable_z2 = 0;  ///< hull cells no flyable z = 2 footprint contains (never seen)
  bool any_no_fly = false;
  /// No-fly zones only (empty otherwise): per position, the flight component it belongs to — the
  /// 4-connected parts of the flyable positions (across the seam too), numbered in order of the
  /// lowest UAV id starting in each (component 0 holds UAV 0) — and -1 where not flyable.
  grid::Grid<int> flight_component;
  int flight_components = 1;
  /// No-fly zones only (empty otherwise): per hull cell, the one flight component that sees it
  /// (docs/model.md §8): that of its z = 1 viewpoint when it is reachable at z = 1, else that of
  /// its z = 2 viewpoint; -1 when unreachable at z = 2 (and for non-hull cells).
  grid::Grid<int> seen_from;
};
inline constexpr std::uint8_t kReachZ2 = 1;
inline constexpr std::uint8_t kReachZ1 = 2;

/// Computes the reachability of every hull cell for footprints s1 (z = 1) and s2 (z = 2) from the
/// start cells. `no_fly` null = none (everything reachable).
Reachability compute_reachability(const HullMask& hull, const NoFlyMask* no_fly, int s1, int s2,
                                  std::span<const grid::Cell> starts);

/// The distance service of a mission: over the flyable positions, each neighbour flight taking the
/// longer of its two planes' steps in `flights` (empty: one step each).
grid::DistanceService make_distance_service(const Reachability& reach,
                                            const grid::FlightSteps& flights = {});

/// Flat indices of the hull cells with (reach & bit) == 0, in increasing order.
std::vector<int> unreachable_cells(const HullMask& hull, const Reachability& reach,
                                   std::uint8_t bit);

}  // namespace hullinspect::world
