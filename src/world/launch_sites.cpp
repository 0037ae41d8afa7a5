#include "hullinspect/world/launch_sites.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/grid/distance.hpp"
#include "hullinspect/grid/distance_service.hpp"
#include "hullinspect/world/standoff_surface.hpp"

namespace hullinspect::world {

namespace {

/// A time option: finite, not negative, and no longer than the mission's time limit in seconds
/// (so that step counts stay far from overflow).
void check_seconds(const char* name, double seconds, const MissionParams& p) {
  const double limit_s = p.time_limit * p.step_seconds();
  if (!std::isfinite(seconds) || seconds < 0.0 || seconds > limit_s) {
    throw ParameterError(name, fmt::format("must be a number of seconds in [0, {}] (the time "
                                           "limit) (got {})",
                                           limit_s, seconds));
  }
}

}  // namespace

void check_launch_site(grid::Cell c, int width, int height,
                       const std::function<bool(grid::Cell)>& is_hull,
                       const std::function<bool(grid::Cell)>& is_no_fly) {
  if (c.x < 0 || c.y < 0 || c.x >= width || c.y >= height) {
    throw ParameterError("launch", fmt::format("site ({}, {}) is outside the {} × {} grid", c.x,
                                               c.y, width, height));
  }
  if (is_no_fly(c)) {
    throw ParameterError("launch", fmt::format("site ({}, {}) is a no-fly position", c.x, c.y));
  }
  const bool edge = c.x == 0 || c.y == 0 || c.x == width - 1 || c.y == height - 1;
  if (is_hull(c) && !edge) {
    throw ParameterError("launch", fmt::format("site ({}, {}) is a hull cell inside the grid (a "
                                               "site is a non-hull cell or on the grid's edge)",
                                               c.x, c.y));
  }
}

void validate_launch_sites(const MissionParams& p, const HullMask& hull) {
  check_seconds("launch-transfer", p.launch_transfer_s, p);
  if (p.takeoff_time_s) check_seconds("takeoff-time", *p.takeoff_time_s, p);
  for (const grid::Cell c : p.launch_sites) {
    check_launch_site(
        c, hull.width(), hull.height(), [&](grid::Cell h) { return hull.is_hull(h); },
        [&](grid::Cell h) { return p.no_fly && (*p.no_fly)[h] != 0; });
  }
}

int LaunchLegs::homeward_steps(int uav, grid::Cell pos, int z, int transit_left) const {
  // Finish a plane change under way; a UAV at (or arriving at) plane 1 climbs to plane 2 first.
  int climb = 0;
  if (transit_left > 0) {
    climb = transit_left + (z == 2 ? plane_change_steps : 0);
  } else if (z == 1) {
    climb = plane_change_steps;
  }
  const auto site = static_cast<std::size_t>(site_of[static_cast<std::size_t>(uav)]);
  return climb + flight_home[site][pos] + takeoff_steps + transfer_steps;
}

std::vector<grid::Cell> LaunchLegs::path_home(int uav, grid::Cell from) const {
  const auto& d = flight_home[static_cast<std::size_t>(site_of[static_cast<std::size_t>(uav)])];
  std::vector<grid::Cell> path;
  grid::Cell c = from;
  while (d[c] > 0) {
    int steps = 1;
    for (const int dir : {1, 0, 3, 2}) {  // west, east, south, north (grid::kNeighbourDx order)
      const grid::Cell n = grid::neighbour(c, dir, d.width(), d.height(), flights);
      if (n == grid::kNoCell) continue;
      const int flight = flights.between(c, n);
      if (d[n] == d[c] - flight) {
        c = n;
        steps = flight;
        break;
      }
    }
    path.insert(path.end(), static_cast<std::size_t>(steps), c);
  }
  return path;
}

LaunchLegs plan_launch_legs(const MissionParams& p, const HullMask& hull, const Reachability& reach,
                            std::span<const grid::Cell> starts) {
  if (p.launch_sites.empty()) return {};
  return plan_launch_legs(p, reach, starts, neighbour_flights(hull, p).plane[1]);
}

LaunchLegs plan_launch_legs(const MissionParams& p, const Reachability& reach,
                            std::span<const grid::Cell> starts, const grid::EdgeSteps& flights) {
  LaunchLegs legs;
  if (p.launch_sites.empty()) return legs;
  legs.flights = flights;
  legs.sites = p.launch_sites;
  legs.plane_change_steps = p.plane_change_steps();
  legs.takeoff_steps =
      p.takeoff_time_s ? p.steps_for_seconds(*p.takeoff_time_s) : legs.plane_change_steps;
  legs.transfer_steps = p.steps_for_seconds(p.launch_transfer_s);

  // The flyable positions plus the sites themselves: a site off the start's component is refused
  // below rather than silently unreachable.
  grid::Grid<std::uint8_t> passable = reach.flyable;
  for (const grid::Cell s : legs.sites) passable[s] = 1;
  grid::BfsScratch scratch;
  // With neighbour flights longer than a step (an unrolled hull), the weighted search of the
  // distance service; a position no UAV may fly is unreachable, as in the breadth-first search.
  std::optional<grid::DistanceService> weighted;
  if (!flights.empty()) weighted.emplace(passable, flights, /*cached_fields=*/1);
  for (const grid::Cell s : legs.sites) {
    grid::Grid<int> d;
    if (weighted) {
      d = weighted->field(s);
      for (int i = 0; i < d.size(); ++i) {
        if (passable[i] == 0) d[i] = grid::kUnreachable;
      }
    } else {
      const int source = passable.index(s.x, s.y);
      grid::bfs_distances(passable, std::span<const int>(&source, 1), d, scratch);
    }
    legs.flight_home.push_back(std::move(d));
  }
  for (std::size_t k = 0; k < starts.size(); ++k) {
    int best = -1;
    for (std::size_t s = 0; s < legs.sites.size(); ++s) {
      const int d = legs.flight_home[s][starts[k]];
      if (d < grid::kUnreachable &&
          (best < 0 || d < legs.flight_home[static_cast<std::size_t>(best)][starts[k]]))
        best = static_cast<int>(s);
    }
    if (best < 0) {
      throw ParameterError("launch", fmt::format("no site can reach UAV {}'s start cell ({}, {}) "
                                                 "in flight (no-fly positions cut them off)",
                                                 k, starts[k].x, starts[k].y));
    }
    legs.site_of.push_back(best);
    const int descent = p.start_z == 1 ? legs.plane_change_steps : 0;
    legs.outbound.push_back(legs.transfer_steps + legs.takeoff_steps +
                            legs.flight_home[static_cast<std::size_t>(best)][starts[k]] + descent);
  }
  return legs;
}

}  // namespace hullinspect::world
