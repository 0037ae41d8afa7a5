#include "hullinspect/io/ship_frame.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "hullinspect/core/errors.hpp"
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
  const int s = z == 1 ? spec_.s1 : spec_.s2;
  const double half = spec_.theta_deg * std::numbers::pi / 360.0;
  return s * spec_.cell_m / (2.0 * std::tan(half));
}

double ShipFrame::depth_m(grid::Cell cell) const {
  if (spec_.depth.size() == 0 || !spec_.depth.contains(cell)) return 0.0;
  return spec_.depth[cell];
}

ShipPose ShipFrame::pose(grid::Cell cell, int z) const {
  ShipPose p;
  p.x = spec_.x0 + (cell.x + 0.5) * spec_.cell_m;
  p.z = spec_.z0 + (cell.y + 0.5) * spec_.cell_m;
  p.y = spec_.ys + sign_ * (standoff_m(z) + depth_m(cell));
  // The camera looks along −normal; a flat side's normal points at the viewer (0, ±1, 0).
  double nx = 0;
  double ny = sign_;
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
    s.side = f->at("side") == "port" ? HullSide::kPort : HullSide::kStarboard;
    const int width = grid.at("width").get<int>();
    const int height = grid.at("height").get<int>();
    s.depth = grid::Grid<double>(width, height, 0.0);
    s.normal = grid::Grid<std::array<double, 3>>(width, height);
    const auto& depth = f->at("depth");
    const auto& normal = f->at("normal");
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const auto ux = static_cast<std::size_t>(x);
        const auto uy = static_cast<std::size_t>(y);
        s.depth(x, y) = depth.at(uy).at(ux).get<double>();
        const auto& n = normal.at(uy).at(ux);
        s.normal(x, y) = {n.at(0).get<double>(), n.at(1).get<double>(), n.at(2).get<double>()};
      }
    }
  }
  return s;
}

}  // namespace hullinspect::io
