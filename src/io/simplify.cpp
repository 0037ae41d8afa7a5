#include "hullinspect/io/simplify.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>

#include <fmt/format.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/io/export.hpp"

namespace hullinspect::io {

namespace {

// How far p lies from the leg a–b, measured at p's position along the leg's main axis (x for a
// leg along the hull, z for one up or down it): the chord's point at that coordinate, so the
// deviation is what the camera's stand-off and height change at p's cell. Infinite when p is
// outside the leg's span on that axis.
double deviation(const ShipPose& p, const ShipPose& a, const ShipPose& b) {
  const bool along_x = std::abs(b.x - a.x) >= std::abs(b.z - a.z);
  const double from = along_x ? a.x : a.z, to = along_x ? b.x : b.z, at = along_x ? p.x : p.z;
  if (to == from) return std::hypot(p.x - a.x, p.y - a.y, p.z - a.z);
  const double t = (at - from) / (to - from);
  if (t < 0 || t > 1) return std::numeric_limits<double>::infinity();
  return std::hypot(p.x - (a.x + t * (b.x - a.x)), p.y - (a.y + t * (b.y - a.y)),
                    p.z - (a.z + t * (b.z - a.z)));
}

// A waypoint a merged leg may skip: the end of a straight move, without a hold of its own.
bool removable(const ExportWaypoint& w) {
  return w.grid.action == WaypointAction::kMove || w.grid.action == WaypointAction::kTransit;
}

}  // namespace

std::vector<ExportWaypoint> simplify_waypoints(const ExportPlan& plan,
                                               std::span<const ExportWaypoint> waypoints,
                                               double tolerance_m) {
  std::vector<ExportWaypoint> out;
  if (waypoints.empty()) return out;
  std::size_t anchor = 0;
  out.push_back(waypoints[0]);
  while (anchor + 1 < waypoints.size()) {
    // Extend the leg from `anchor` to `end` while every skipped waypoint is a plain move on the
    // anchor's plane within the tolerance of the straight leg.
    std::size_t end = anchor + 1;
    while (end + 1 < waypoints.size() && removable(waypoints[end]) &&
           waypoints[end + 1].grid.z == waypoints[anchor].grid.z) {
      bool within = true;
      for (std::size_t k = anchor + 1; k <= end && within; ++k) {
        within = deviation(waypoints[k].pose, waypoints[anchor].pose, waypoints[end + 1].pose) <=
                 tolerance_m / 2;
      }
      if (!within) break;
      ++end;
    }
    ExportWaypoint merged = waypoints[end];
    if (end > anchor + 1) {
      // The merged leg takes the steps of the legs it replaces.
      merged.grid.duration = waypoints[end].grid.t - waypoints[anchor].grid.t;
    }
    out.push_back(merged);
    anchor = end;
  }
  // Half the tolerance outward (away from the surface): a merged leg that cuts inside a convex
  // curve by up to half the tolerance still flies no closer than its plane, so its footprints are
  // never smaller than the planned ones; every point stays within the tolerance of the plan.
  const double outward = plan.frame.spec().side == HullSide::kPort ? 1.0 : -1.0;
  for (auto& w : out) w.pose.y += outward * tolerance_m / 2;
  return out;
}

void mark_seen(const ExportPlan& plan, std::span<const ExportWaypoint> waypoints,
               std::vector<std::vector<char>>& seen) {
  const auto& spec = plan.frame.spec();
  const double cell = spec.cell_m;
  const double tan_half = std::tan(spec.theta_deg * std::numbers::pi / 360.0);
  const double sign = spec.side == HullSide::kPort ? 1.0 : -1.0;
  const auto look = [&](double x, double y, double z) {
    const grid::Cell c = plan.frame.cell_at(x, z);
    const double from_surface = sign * (y - spec.ys) - plan.frame.depth_m(c);
    // Cells whose centres lie within reach of the axis (a small slack for rounding).
    const double reach = from_surface * tan_half - cell / 2 + 1e-6;
    if (reach < 0) return;
    const int r = static_cast<int>(std::floor(reach / cell)) + 1;
    for (int dy = -r; dy <= r; ++dy) {
      for (int dx = -r; dx <= r; ++dx) {
        const grid::Cell n{c.x + dx, c.y + dy};
        if (n.y < 0 || n.x < 0 || static_cast<std::size_t>(n.y) >= seen.size() ||
            static_cast<std::size_t>(n.x) >= seen[static_cast<std::size_t>(n.y)].size()) {
          continue;
        }
        const double cx = spec.x0 + (n.x + 0.5) * cell;
        const double cz = spec.z0 + (n.y + 0.5) * cell;
        if (std::abs(cx - x) <= reach && std::abs(cz - z) <= reach) {
          seen[static_cast<std::size_t>(n.y)][static_cast<std::size_t>(n.x)] = 1;
        }
      }
    }
  };
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    const auto& b = waypoints[i].pose;
    if (i == 0) {
      look(b.x, b.y, b.z);
      continue;
    }
    const auto& a = waypoints[i - 1].pose;
    // Samples where the leg crosses a cell centre's x or z (so a planned path is sampled exactly
    // at its cells), and its end.
    std::vector<double> ts = {1.0};
    for (const auto& [from, to, origin] :
         {std::tuple{a.x, b.x, spec.x0}, std::tuple{a.z, b.z, spec.z0}}) {
      if (from == to) continue;
      const double lo = std::min(from, to), hi = std::max(from, to);
      for (double c = std::ceil((lo - origin) / cell - 0.5); origin + (c + 0.5) * cell <= hi; ++c) {
        ts.push_back((origin + (c + 0.5) * cell - from) / (to - from));
      }
    }
    for (const double t : ts) {
      look(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z));
    }
  }
}

std::optional<grid::Cell> first_cell_lost(const ExportPlan& plan,
                                          std::span<const ExportWaypoint> original,
                                          std::span<const ExportWaypoint> simplified) {
  const auto empty =
      std::vector<std::vector<char>>(static_cast<std::size_t>(plan.height),
                                     std::vector<char>(static_cast<std::size_t>(plan.width), 0));
  auto before = empty;
  auto after = empty;
  mark_seen(plan, original, before);
  mark_seen(plan, simplified, after);
  for (int y = 0; y < plan.height; ++y) {
    for (int x = 0; x < plan.width; ++x) {
      const auto ys = static_cast<std::size_t>(y), xs = static_cast<std::size_t>(x);
      if (before[ys][xs] && !after[ys][xs]) return grid::Cell{x, y};
    }
  }
  return std::nullopt;
}

void simplify_sortie(const ExportPlan& plan, Sortie& sortie, double tolerance_m) {
  // The coverage check below measures footprints against one side plane; an unrolled hull's
  // waypoints face every direction around the ship.
  if (plan.frame.unrolled()) {
    throw ParameterError("simplify",
                         "is not available for an unrolled hull (--sides both): its legs follow a "
                         "curved surface that the coverage check cannot measure");
  }
  const auto all = std::span<const ExportWaypoint>(sortie.waypoints);
  const auto in = static_cast<std::size_t>(sortie.transit_in);
  const auto out = static_cast<std::size_t>(sortie.transit_out);
  const auto flown = all.subspan(in, all.size() - in - out);
  const auto simplified_in = simplify_waypoints(plan, all.subspan(0, in), tolerance_m);
  const auto simplified = simplify_waypoints(plan, flown, tolerance_m);
  const auto simplified_out = simplify_waypoints(plan, all.subspan(all.size() - out), tolerance_m);
  if (const auto lost = first_cell_lost(plan, flown, simplified)) {
    throw ParameterError("simplify",
                         fmt::format("{} m would lose coverage of cell {},{} (UAV {}); give a "
                                     "smaller tolerance",
                                     tolerance_m, lost->x, lost->y, sortie.uav));
  }
  std::vector<ExportWaypoint> waypoints = simplified_in;
  waypoints.insert(waypoints.end(), simplified.begin(), simplified.end());
  waypoints.insert(waypoints.end(), simplified_out.begin(), simplified_out.end());
  sortie.transit_in = static_cast<int>(simplified_in.size());
  sortie.transit_out = static_cast<int>(simplified_out.size());
  sortie.waypoints = std::move(waypoints);
}

}  // namespace hullinspect::io
