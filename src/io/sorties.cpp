#include "hullinspect/io/sorties.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <deque>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/io/export.hpp"
#include "hullinspect/world/launch_sites.hpp"

namespace hullinspect::io {

std::size_t nearest_site(grid::Cell start, const std::vector<grid::Cell>& sites) {
  std::size_t best = 0;
  long best_d2 = -1;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const long dx = sites[i].x - start.x;
    const long dy = sites[i].y - start.y;
    const long d2 = dx * dx + dy * dy;
    if (best_d2 < 0 || d2 < best_d2) {
      best = i;
      best_d2 = d2;
    }
  }
  return best;
}

namespace {

// The mission's rule for a site (world/launch_sites.hpp), over the trace's grid.
void check_site(const ExportPlan& plan, grid::Cell s) {
  world::check_launch_site(
      s, plan.width, plan.height, [&plan](grid::Cell c) { return plan.is_hull(c); },
      [&plan](grid::Cell c) {
        return std::find(plan.no_fly.begin(), plan.no_fly.end(), c) != plan.no_fly.end();
      });
}

// The shortest 4-connected path over allowed positions from `from` to `to` (both included).
std::vector<grid::Cell> allowed_path(const ExportPlan& plan, grid::Cell from, grid::Cell to) {
  const auto index = [&plan](grid::Cell c) {
    return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(plan.width) +
           static_cast<std::size_t>(c.x);
  };
  const std::size_t n =
      static_cast<std::size_t>(plan.width) * static_cast<std::size_t>(plan.height);
  std::vector<char> blocked(n, 0);
  for (const auto& c : plan.no_fly) blocked[index(c)] = 1;
  std::vector<long> parent(n, -2);
  std::deque<grid::Cell> queue{from};
  parent[index(from)] = -1;
  while (!queue.empty()) {
    const auto c = queue.front();
    queue.pop_front();
    if (c == to) break;
    for (const grid::Cell d : {grid::Cell{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const grid::Cell next{c.x + d.x, c.y + d.y};
      if (next.x < 0 || next.y < 0 || next.x >= plan.width || next.y >= plan.height) continue;
      const auto i = index(next);
      if (blocked[i] || parent[i] != -2) continue;
      parent[i] = static_cast<long>(index(c));
      queue.push_back(next);
    }
  }
  if (parent[index(to)] == -2) return {};
  std::vector<grid::Cell> path;
  for (long i = static_cast<long>(index(to)); i >= 0; i = parent[static_cast<std::size_t>(i)]) {
    path.push_back({static_cast<int>(i % plan.width), static_cast<int>(i / plan.width)});
  }
  std::reverse(path.begin(), path.end());
  return path;
}

// The waypoints of a plane-2 flight along `path`, collinear moves merged as in the trace's own
// waypoints; times count from `t0`, one step a move.
std::vector<ExportWaypoint> transit(const ExportPlan& plan, const std::vector<grid::Cell>& path,
                                    int t0) {
  std::vector<GridState> states;
  for (const auto& c : path) states.push_back({c, 2, false, true});
  const auto same = [&plan](grid::Cell a, grid::Cell b) { return plan.frame.same_surface(a, b); };
  std::vector<ExportWaypoint> out;
  for (auto w : compress_trajectory(states, same)) {
    w.t += t0;
    if (w.action == WaypointAction::kMove) w.action = WaypointAction::kTransit;
    out.push_back({w, plan.frame.pose(w.cell, w.z)});
  }
  return out;
}

// The take-off and landing point below a site: its plane-2 position at the grid's bottom edge.
ShipPose home_below(const ExportPlan& plan, grid::Cell site) {
  const auto p = plan.frame.pose(site, 2);
  return {p.x, p.y, plan.frame.spec().z0, p.yaw};
}

// UAV k's sorties of a battery-limited mission: each the trace's frames from its take-off to its
// landing (or the last frame), compressed on its own, so that every file starts at the site and
// ends there.
std::vector<Sortie> cut_sorties(const ExportPlan& plan, const std::vector<grid::Cell>& sites,
                                std::size_t k, const std::vector<FlownSortie>& flown) {
  const auto& states = plan.states[k];
  const auto same = [&plan](grid::Cell a, grid::Cell b) { return plan.frame.same_surface(a, b); };
  std::vector<Sortie> out;
  if (states.empty()) return out;  // a UAV with no recorded state flew no sortie
  for (std::size_t n = 0; n < flown.size(); ++n) {
    const auto& f = flown[n];
    if (f.site < 0 || static_cast<std::size_t>(f.site) >= sites.size()) {
      throw ParameterError("launch", fmt::format("UAV {}'s sortie {} lands at launch site {}, but "
                                                 "{} site{} given",
                                                 k, n + 1, f.site, sites.size(),
                                                 sites.size() == 1 ? " is" : "s are"));
    }
    const auto last = static_cast<int>(states.size()) - 1;
    const int begin = std::clamp(f.takeoff, 0, last);
    const int end = f.landing < 0 ? last : std::clamp(f.landing, begin, last);
    Sortie s;
    s.uav = static_cast<int>(k);
    s.number = static_cast<int>(n) + 1;
    s.site = sites[static_cast<std::size_t>(f.site)];
    s.given_site = true;
    s.flown = true;
    const auto slice = std::span<const GridState>(states).subspan(
        static_cast<std::size_t>(begin), static_cast<std::size_t>(end - begin + 1));
    for (auto w : compress_trajectory(slice, same)) {
      w.t += begin;  // the trace's clock
      s.waypoints.push_back({w, plan.frame.pose(w.cell, w.z)});
    }
    s.home = home_below(plan, s.site);
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace

std::vector<Sortie> plan_sorties(const ExportPlan& plan, const std::vector<grid::Cell>& sites,
                                 const std::vector<std::vector<FlownSortie>>& flown_sorties) {
  for (const auto& s : sites) check_site(plan, s);
  std::vector<Sortie> sorties;
  for (std::size_t k = 0; k < plan.uavs.size(); ++k) {
    if (k < flown_sorties.size() && !flown_sorties[k].empty()) {
      for (auto& s : cut_sorties(plan, sites, k, flown_sorties[k])) sorties.push_back(std::move(s));
      continue;
    }
    const auto& flown = plan.uavs[k];
    Sortie s;
    s.uav = static_cast<int>(k);
    if (flown.empty()) continue;
    const auto& first = flown.front();
    const auto& last = flown.back();
    s.given_site = !sites.empty();
    s.site = sites.empty() ? first.grid.cell : sites[nearest_site(first.grid.cell, sites)];
    if (s.given_site) {
      // To the plan's start on plane 2 (a start on plane 1 then descends as its first waypoint).
      const auto in = allowed_path(plan, s.site, first.grid.cell);
      const auto out = allowed_path(plan, last.grid.cell, s.site);
      if (in.empty() || out.empty()) {
        throw ParameterError("launch", fmt::format("no allowed path joins the launch site {},{} "
                                                   "to UAV {}'s flight",
                                                   s.site.x, s.site.y, k));
      }
      // Times before the plan's start are negative: the trace's clock starts at the plan.
      auto legs_in = transit(plan, in, -static_cast<int>(in.size() - 1));
      legs_in.front().grid.action = WaypointAction::kStart;
      // The last transit waypoint is the plan's start cell on plane 2: kept only when the plan
      // starts on plane 1 (its start waypoint is then the descent).
      if (first.grid.z == 2) legs_in.pop_back();
      s.waypoints = legs_in;
      s.transit_in = static_cast<int>(legs_in.size());
      s.waypoints.insert(s.waypoints.end(), flown.begin(), flown.end());
      if (first.grid.z != 2) {  // the plan's start on plane 1 is reached by a descent
        auto& start = s.waypoints[static_cast<std::size_t>(s.transit_in)].grid;
        start.action = WaypointAction::kPlaneChange;
        start.duration = plan.plane_change_steps;
      }
      // Back: climb to plane 2 first if the plan ends on plane 1, then the path home.
      if (last.grid.z != 2) {
        ExportWaypoint up{{last.grid.t + plan.plane_change_steps, last.grid.cell, 2,
                           WaypointAction::kPlaneChange, plan.plane_change_steps},
                          plan.frame.pose(last.grid.cell, 2)};
        s.waypoints.push_back(up);
        ++s.transit_out;
      }
      const int t_back = s.waypoints.back().grid.t;
      auto legs_out = transit(plan, out, t_back);
      for (std::size_t i = 1; i < legs_out.size(); ++i) {  // [0] is where the plan ended
        s.waypoints.push_back(legs_out[i]);
        ++s.transit_out;
      }
    } else {
      s.waypoints = flown;
    }
    s.home = home_below(plan, s.site);
    sorties.push_back(std::move(s));
  }
  return sorties;
}

std::vector<MissionPart> split_sortie(const Sortie& sortie, int cap) {
  if (cap != 0 && cap < kMinWaypointCap) {
    throw ParameterError(
        "max-waypoints",
        fmt::format("{} is below the {} waypoints a mission file needs (the point it starts from "
                    "and one to fly to)",
                    cap, kMinWaypointCap));
  }
  std::vector<MissionPart> parts;
  const std::span<const ExportWaypoint> all(sortie.waypoints);
  const std::size_t n = all.size();
  const std::size_t size = cap == 0 ? std::max<std::size_t>(n, 1) : static_cast<std::size_t>(cap);
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = std::min(n, begin + size);
    parts.push_back(
        {&sortie, static_cast<int>(parts.size()) + 1, 0, all.subspan(begin, end - begin)});
    if (end >= n) break;
    begin = end - 1;  // the next part starts where this one ended
  }
  for (auto& p : parts) p.parts = static_cast<int>(parts.size());
  return parts;
}

}  // namespace hullinspect::io
