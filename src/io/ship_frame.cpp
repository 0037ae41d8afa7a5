#include "hullinspect/io/ship_frame.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/grid/flight_steps.hpp"
#include "hullinspect/world/ship_frame_bounds.hpp"

namespace hullinspect::io {

ShipFrame::ShipFrame(ShipFrameSpec spec)
    : spec_(std::move(spec)), sign_(spec_.side == HullSide::kPort ? 1.0 : -1.0) {
  // Speeds and hold times divide by the cell side (cruise speed = one cell per step).
  if (!(spec_.cell_m >= world::kMinCellSizeM && spec_.cell_m <= world::kMaxCellSizeM)) {
    throw InputError(spec_.source, 0,
                     fmt::format("the cell size {} m is outside [{}, {}] m", spec_.cell_m,
                                 world::kMinCellSizeM, world::kMaxCellSizeM));
  }
}

double ShipFrame::standoff_m(int z) const {
  return grid::standoff_m(z == 1 ? spec_.s1 : spec_.s2, spec_.cell_m, spec_.theta_deg);
}

double ShipFrame::depth_m(grid::Cell cell) const {
  if (spec_.depth.size() == 0 || !spec_.depth.contains(cell)) return 0.0;
  return spec_.depth[cell];
}

std::array<double, 3> ShipFrame::surface_point(grid::Cell cell) const {
  if (unrolled()) {
    if (!spec_.surface.contains(cell)) {
      throw InputError(spec_.source, 0,
                       fmt::format("cell ({}, {}) is outside the unrolled hull's {} × {} grid",
                                   cell.x, cell.y, spec_.surface.width(), spec_.surface.height()));
    }
    return spec_.surface[cell];
  }
  return {spec_.x0 + (cell.x + 0.5) * spec_.cell_m, spec_.ys + sign_ * depth_m(cell),
          spec_.z0 + (cell.y + 0.5) * spec_.cell_m};
}

ShipPose ShipFrame::pose(grid::Cell cell, int z) const {
  ShipPose p;
  // The camera looks along −normal; a flat side's normal points at the viewer (0, ±1, 0).
  double nx = 0;
  double ny = sign_;
  if (unrolled()) {
    if (!spec_.surface.contains(cell) || !spec_.normal.contains(cell)) {
      throw InputError(spec_.source, 0,
                       fmt::format("cell ({}, {}) is outside the unrolled hull's {} × {} grid",
                                   cell.x, cell.y, spec_.surface.width(), spec_.surface.height()));
    }
    // The stand-off is along the normal; a face seen from above or below (n horizontal part 0)
    // keeps the yaw toward the centre plane.
    const auto& s = spec_.surface[cell];
    const auto& n = spec_.normal[cell];
    const double d = standoff_m(z);
    p.x = s[0] + d * n[0];
    p.y = s[1] + d * n[1];
    p.z = s[2] + d * n[2];
    ny = s[1] >= spec_.ys ? 1.0 : -1.0;
  } else {
    p.x = spec_.x0 + (cell.x + 0.5) * spec_.cell_m;
    p.z = spec_.z0 + (cell.y + 0.5) * spec_.cell_m;
    p.y = spec_.ys + sign_ * (standoff_m(z) + depth_m(cell));
  }
  if (spec_.normal.size() != 0 && spec_.normal.contains(cell)) {
    const auto& n = spec_.normal[cell];
    if (std::hypot(n[0], n[1]) > 1e-9) {  // a horizontal face (deck, keel) keeps the side's yaw
      nx = n[0];
      ny = n[1];
    }
  }
  p.yaw = std::atan2(-ny, -nx);
  const auto within = [](double v) { return std::abs(v) <= world::kMaxShipFrameM; };
  if (!within(p.x) || !within(p.y) || !within(p.z) || !std::isfinite(p.yaw)) {
    throw InputError(spec_.source, 0,
                     fmt::format("the waypoint of cell ({}, {}) at z = {} lies at ship-frame "
                                 "({}, {}, {}) m; expected finite metres within ±{} (check the "
                                 "cell size, θ and the origin)",
                                 cell.x, cell.y, z, p.x, p.y, p.z, world::kMaxShipFrameM));
  }
  return p;
}

bool ShipFrame::same_surface(grid::Cell a, grid::Cell b) const {
  if (unrolled()) {
    // One plane: the same normal and the same offset n·S (a straight leg between two points at
    // one stand-off from a plane stays at that stand-off). The surface points are kept to 0.1 mm.
    if (!spec_.normal.contains(a) || !spec_.normal.contains(b)) return false;
    const auto& n = spec_.normal[a];
    if (n != spec_.normal[b]) return false;
    const auto& sa = spec_.surface[a];
    const auto& sb = spec_.surface[b];
    const double offset = n[0] * (sa[0] - sb[0]) + n[1] * (sa[1] - sb[1]) + n[2] * (sa[2] - sb[2]);
    return std::abs(offset) < 1e-3;
  }
  if (depth_m(a) != depth_m(b)) return false;
  if (spec_.normal.size() == 0) return true;
  const bool ia = spec_.normal.contains(a);
  const bool ib = spec_.normal.contains(b);
  return ia == ib && (!ia || spec_.normal[a] == spec_.normal[b]);
}

grid::Cell ShipFrame::cell_at(double x, double z) const {
  return {static_cast<int>(std::floor((x - spec_.x0) / spec_.cell_m)),
          static_cast<int>(std::floor((z - spec_.z0) / spec_.cell_m))};
}

int ShipFrame::plane_at(grid::Cell cell, double y, double tolerance_m) const {
  const double off = sign_ * (y - spec_.ys) - depth_m(cell);
  int best = 0;
  double best_error = tolerance_m;
  for (int z : {1, 2}) {
    const double e = std::abs(off - standoff_m(z));
    if (e <= best_error) {
      best = z;
      best_error = e;
    }
  }
  return best;
}

ShipFrame::Located ShipFrame::locate(double x, double y, double z, double tolerance_m) const {
  Located found;
  if (!unrolled()) {
    found.cell = cell_at(x, z);
    found.plane = plane_at(found.cell, y, tolerance_m);
    return found;
  }
  // Every cell's two poses: the nearest one within the tolerance.
  double best = tolerance_m;
  for (int cy = 0; cy < spec_.surface.height(); ++cy) {
    for (int cx = 0; cx < spec_.surface.width(); ++cx) {
      const auto& s = spec_.surface(cx, cy);
      const auto& n = spec_.normal(cx, cy);
      for (int plane : {1, 2}) {
        const double d = standoff_m(plane);
        const double e = std::hypot(s[0] + d * n[0] - x, s[1] + d * n[1] - y, s[2] + d * n[2] - z);
        if (e <= best) {
          best = e;
          found = {{cx, cy}, plane};
        }
      }
    }
  }
  return found;
}

ShipFrameSpec ship_frame_spec(const nlohmann::json& trace, const std::string& source) {
  ShipFrameSpec s;
  s.source = source;
  const auto& grid = trace.at("grid");
  s.cell_m = grid.at("cell_size_m").get<double>();
  s.s1 = trace.at("footprint").at(0).get<int>();
  s.s2 = trace.at("footprint").at(1).get<int>();
  if (auto c = trace.find("camera"); c != trace.end() && c->contains("theta_deg")) {
    s.theta_deg = c->at("theta_deg").get<double>();
  } else if (auto p = trace.at("parameters").find("theta");
             p != trace.at("parameters").end() && p->is_number()) {
    s.theta_deg = p->get<double>();
  }
  // A hull imported from a mesh (docs/trace-format.md): the waypoints stand off from its surface.
  if (auto f = trace.find("ship_frame"); f != trace.end()) {
    s.x0 = f->at("origin").at(0).get<double>();
    s.z0 = f->at("origin").at(1).get<double>();
    s.ys = f->at("side_plane_y").get<double>();
    const auto& side = f->at("side");
    s.side = side == "port" ? HullSide::kPort
                            : (side == "both" ? HullSide::kBoth : HullSide::kStarboard);
    const int width = grid.at("width").get<int>();
    const int height = grid.at("height").get<int>();
    const auto vector = [](const nlohmann::json& v) -> std::array<double, 3> {
      return {v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>()};
    };
    s.depth = grid::Grid<double>(width, height, 0.0);
    s.normal = grid::Grid<std::array<double, 3>>(width, height);
    if (s.side == HullSide::kBoth) s.surface = grid::Grid<std::array<double, 3>>(width, height);
    const auto& normal = f->at("normal");
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const auto ux = static_cast<std::size_t>(x);
        const auto uy = static_cast<std::size_t>(y);
        s.normal(x, y) = vector(normal.at(uy).at(ux));
        if (s.side == HullSide::kBoth) {
          s.surface(x, y) = vector(f->at("surface").at(uy).at(ux));
        } else {
          s.depth(x, y) = f->at("depth").at(uy).at(ux).get<double>();
        }
      }
    }
  }
  return s;
}

}  // namespace hullinspect::io
