#include "hullinspect/world/instance.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/random.hpp"

namespace hullinspect::world {

CorrosionParams CorrosionParams::homogeneous(int a, double p_c, int l_c, double p_tp, double p_fp) {
  CorrosionParams p;
  p.zones = {CorrosionZone{0, a, p_c, l_c}};
  p.p_tp = p_tp;
  p.p_fp = p_fp;
  return p;
}

CorrosionParams CorrosionParams::front_back(int a, double back_p_c, int back_l_c, double front_p_c,
                                            int front_l_c, double p_tp, double p_fp) {
  CorrosionParams p;
  p.zones = {CorrosionZone{0, a / 2, back_p_c, back_l_c}, CorrosionZone{a / 2, a, front_p_c, front_l_c}};
  p.p_tp = p_tp;
  p.p_fp = p_fp;
  return p;
}

void validate(const CorrosionParams& p, const HullMask& hull) {
  auto probability = [](const char* name, double v) {
    if (!(v >= 0.0 && v <= 1.0)) {
      throw ParameterError(name, fmt::format("must be a probability in [0, 1] (got {})", v));
    }
  };
  probability("p_tp", p.p_tp);
  probability("p_fp", p.p_fp);
  int covered_to = 0;
  for (const auto& z : p.zones) {
    probability("p_c", z.p_c);
    if (z.l_c < 1 || z.l_c % 2 == 0 || z.l_c > kMaxGridSide) {
      throw ParameterError("l_c", fmt::format("must be a positive odd integer (got {})", z.l_c));
    }
    if (z.x_begin != covered_to || z.x_end <= z.x_begin) {
      throw ParameterError("zones", fmt::format("must be consecutive non-empty column ranges from "
                                                "x = 0 (zone [{}, {}) does not follow x = {})",
                                                z.x_begin, z.x_end, covered_to));
    }
    covered_to = z.x_end;
  }
  if (!p.zones.empty() && covered_to < hull.width()) {
    throw ParameterError("zones", fmt::format("cover x < {} but the grid is {} wide", covered_to,
                                              hull.width()));
  }
}

int Instance::corroded_cells() const {
  return static_cast<int>(std::count(truth.values().begin(), truth.values().end(), 1));
}

namespace {

const CorrosionZone& zone_of(const std::vector<CorrosionZone>& zones, int x) {
  for (const auto& z : zones) {
    if (x < z.x_end) return z;
  }
  return zones.back();
}

// A rectangle side uniform over the odd integers {1, 3, …, l_c}.
int odd_side(RandomStream& rng, int l_c) {
  return 2 * static_cast<int>(rng.below(static_cast<std::uint64_t>((l_c + 1) / 2))) + 1;
}

struct Rectangle {
  int cx, cy, w, h;
};

void paint(grid::Grid<std::int8_t>& m, const HullMask& hull, const Rectangle& r) {
  for (int y = std::max(0, r.cy - r.h / 2); y <= std::min(m.height() - 1, r.cy + r.h / 2); ++y) {
    for (int x = std::max(0, r.cx - r.w / 2); x <= std::min(m.width() - 1, r.cx + r.w / 2); ++x) {
      if (hull.is_hull(x, y)) m(x, y) = 1;
    }
  }
}

}  // namespace

Instance generate_instance(const HullMask& hull, const CorrosionParams& params, std::uint64_t seed) {
  CorrosionParams p = params;
  if (p.zones.empty()) p.zones = {CorrosionZone{0, hull.width(), 0.005, 5}};
  validate(p, hull);

  Instance inst;
  inst.seed = seed;
  inst.truth = grid::Grid<std::int8_t>(hull.width(), hull.height(), -1);
  for (int i : hull.cells()) inst.truth[i] = 0;
  inst.prior = inst.truth;

  // Step 1 and the ground-truth rectangles: one stream, hull cells in (y, x) order, one uniform per
  // cell and two sides per centre.
  RandomStream truth_rng(seed, Stream::kTruth);
  std::vector<Rectangle> truth_rects;
  std::vector<std::uint8_t> is_centre(static_cast<std::size_t>(hull.mask().size()), 0);
  for (int i : hull.cells()) {
    const grid::Cell c = hull.mask().cell(i);
    const CorrosionZone& z = zone_of(p.zones, c.x);
    if (truth_rng.bernoulli(z.p_c)) {
      const int w = odd_side(truth_rng, z.l_c);
      const int h = odd_side(truth_rng, z.l_c);
      truth_rects.push_back({c.x, c.y, w, h});
      is_centre[static_cast<std::size_t>(i)] = 1;
    }
  }
  for (const auto& r : truth_rects) paint(inst.truth, hull, r);
  inst.truth_centres = static_cast<int>(truth_rects.size());

  // Step 2: true positives keep their rectangle; one uniform per ground-truth centre.
  RandomStream tp_rng(seed, Stream::kPriorTp);
  for (const auto& r : truth_rects) {
    if (tp_rng.bernoulli(p.p_tp)) {
      paint(inst.prior, hull, r);
      ++inst.prior_true_positive_centres;
    }
  }
  // Step 3: false positives; one uniform per non-centre hull cell, two sides per false centre.
  RandomStream fp_rng(seed, Stream::kPriorFp);
  for (int i : hull.cells()) {
    if (is_centre[static_cast<std::size_t>(i)]) continue;
    if (!fp_rng.bernoulli(p.p_fp)) continue;
    const grid::Cell c = hull.mask().cell(i);
    const CorrosionZone& z = zone_of(p.zones, c.x);
    const int w = odd_side(fp_rng, z.l_c);
    const int h = odd_side(fp_rng, z.l_c);
    paint(inst.prior, hull, {c.x, c.y, w, h});
    ++inst.prior_false_positive_centres;
  }
  return inst;
}

}  // namespace hullinspect::world
