#pragma once
// Instances (model.md §2): the ground truth C and the prior C' drawn from corrosion parameters and
// a seed.

#include <cstdint>
#include <vector>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::world {

/// Corrosion parameters of one zone: the columns [x_begin, x_end) of the grid.
struct CorrosionZone {
  int x_begin = 0;
  int x_end = 0;       ///< exclusive; clipped to the grid width
  double p_c = 0.005;  ///< probability that a hull cell is a ground-truth centre
  int l_c = 5;         ///< largest rectangle side, odd
};

struct CorrosionParams {
  /// Zones covering the grid along x; empty means one zone with the defaults over the whole grid.
  std::vector<CorrosionZone> zones;
  double p_tp = 1.0;  ///< probability that a ground-truth centre is also a prior centre
  double p_fp = 0.0;  ///< probability that another hull cell is a false-positive prior centre

  /// One zone over a grid of width a.
  static CorrosionParams homogeneous(int a, double p_c, int l_c, double p_tp = 1.0,
                                     double p_fp = 0.0);
  /// Two zones: back x < a/2 and front x >= a/2 (model.md §2 inhomogeneous instances).
  static CorrosionParams front_back(int a, double back_p_c, int back_l_c, double front_p_c,
                                    int front_l_c, double p_tp = 1.0, double p_fp = 0.0);
};

/// Throws ParameterError naming the field ("p_c", "l_c", "p_tp", "p_fp", "zones").
void validate(const CorrosionParams& params, const HullMask& hull);

/// Matrix values as in the paper: -1 not hull, 0 not corroded, 1 corroded.
struct Instance {
  grid::Grid<std::int8_t> truth;  ///< C
  grid::Grid<std::int8_t> prior;  ///< C'
  int truth_centres = 0;
  int prior_true_positive_centres = 0;
  int prior_false_positive_centres = 0;
  std::uint64_t seed = 0;
  int corroded_cells() const;  ///< #{C = 1}
};

/// Draws C and C' (model.md §2). C depends only on (seed, hull, zones); the prior uses separate
/// streams of the same seed, so sweeping p_tp or p_fp keeps C.
Instance generate_instance(const HullMask& hull, const CorrosionParams& params, std::uint64_t seed);

}  // namespace hullinspect::world
