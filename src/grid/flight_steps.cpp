#include "hullinspect/grid/flight_steps.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hullinspect::grid {

int flight_steps_for(double cells) {
  const double steps = std::ceil(cells - kFlightSlackCells);
  if (!(steps > 1)) return 1;
  return steps >= kMaxFlightSteps ? kMaxFlightSteps : static_cast<int>(steps);
}

int EdgeSteps::longest() const {
  int most = 1;
  for (std::uint8_t s : east.values()) most = std::max<int>(most, s);
  for (std::uint8_t s : north.values()) most = std::max<int>(most, s);
  for (std::uint8_t s : seam) most = std::max<int>(most, s);
  return most;
}

EdgeSteps FlightSteps::longer_plane() const {
  if (empty()) return {};
  EdgeSteps out = plane[0];
  for (int i = 0; i < out.east.size(); ++i) {
    out.east[i] = std::max(out.east[i], plane[1].east[i]);
    out.north[i] = std::max(out.north[i], plane[1].north[i]);
  }
  for (std::size_t y = 0; y < out.seam.size(); ++y) {
    out.seam[y] = std::max(out.seam[y], plane[1].seam[y]);
  }
  return out;
}

double standoff_m(int side, double cell_m, double theta_deg) {
  const double half = theta_deg * std::numbers::pi / 360.0;
  return side * cell_m / (2.0 * std::tan(half));
}

FlightSteps flight_steps(const StandoffPoints& points, double cell_m, double theta_deg, int s1,
                         int s2) {
  FlightSteps out;
  const int w = points.point.width();
  const int h = points.point.height();
  if (points.point.size() == 0 || !(cell_m > 0)) return out;
  const auto at = [&](int x, int y, double zeta) {
    const auto& s = points.point(x, y);
    const auto& n = points.normal(x, y);
    return std::array<double, 3>{s[0] + zeta * n[0], s[1] + zeta * n[1], s[2] + zeta * n[2]};
  };
  const auto steps = [&](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return flight_steps_for(std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) / cell_m);
  };
  bool longer = false;
  const double zeta[2] = {standoff_m(s1, cell_m, theta_deg), standoff_m(s2, cell_m, theta_deg)};
  for (int z = 0; z < 2; ++z) {
    EdgeSteps& e = out.plane[static_cast<std::size_t>(z)];
    e.east = Grid<std::uint8_t>(w, h, 1);
    e.north = Grid<std::uint8_t>(w, h, 1);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const auto here = at(x, y, zeta[z]);
        if (x + 1 < w) e.east(x, y) = static_cast<std::uint8_t>(steps(here, at(x + 1, y, zeta[z])));
        if (y + 1 < h)
          e.north(x, y) = static_cast<std::uint8_t>(steps(here, at(x, y + 1, zeta[z])));
        longer = longer || e.east(x, y) > 1 || e.north(x, y) > 1;
      }
    }
    // The seam: every row's two ends, at the stand-off distance between them.
    if (points.seam && w > 2) {
      e.seam.resize(static_cast<std::size_t>(h));
      for (int y = 0; y < h; ++y) {
        e.seam[static_cast<std::size_t>(y)] =
            static_cast<std::uint8_t>(steps(at(0, y, zeta[z]), at(w - 1, y, zeta[z])));
      }
    }
  }
  if (!longer && out.plane[0].seam.empty()) return {};
  return out;
}

}  // namespace hullinspect::grid
