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

// Waypoints of frames [a, b) of `states` (the trace's frames t0, t0 + 1, …), compressed on their
// own; `transit`: their legs are flights between a launch site and the hull.
std::vector<ExportWaypoint> flight_piece(const ExportPlan& plan, std::span<const GridState> states,
                                         int t0, std::size_t a, std::size_t b, bool transit) {
  const auto same = [&plan](grid::Cell p, grid::Cell q) { return plan.frame.same_surface(p, q); };
  std::vector<ExportWaypoint> out;
  for (auto w : compress_trajectory(states.subspan(a, b - a), same)) {
    w.t += t0 + static_cast<int>(a);
    if (transit && w.action == WaypointAction::kMove) w.action = WaypointAction::kTransit;
    out.push_back({w, plan.frame.pose(w.cell, w.z)});
  }
  return out;
}

// The take-off and landing point below a site: its plane-2 position at the ground's height
// (unset: the grid's bottom edge).
ShipPose home_below(const ExportPlan& plan, grid::Cell site, std::optional<double> home_z) {
  const auto p = plan.frame.pose(site, 2);
  return {p.x, p.y, home_z.value_or(plan.frame.spec().z0), p.yaw};
}

// UAV k's sorties of a battery-limited mission: each the trace's frames from its take-off to its
// landing (or the last frame), compressed on its own, so that every file starts at the site and
// ends there; its flights out and home are its transit.
std::vector<Sortie> cut_sorties(const ExportPlan& plan, const std::vector<grid::Cell>& sites,
                                std::size_t k, const std::vector<FlownSortie>& flown) {
  const auto& states = plan.states[k];
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
    auto flight = compress_flight(plan, slice, begin);  // times stay the trace's
    s.waypoints = std::move(flight.waypoints);
    s.transit_in = flight.transit_in;
    s.transit_out = flight.transit_out;
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace

Flight compress_flight(const ExportPlan& plan, std::span<const GridState> states, int t0) {
  Flight f;
  if (states.empty()) return f;
  // The frames up to the last one the UAV was active in (a failed UAV flies no further).
  std::size_t end = states.size();
  while (end > 1 && !states[end - 1].active) --end;
  std::size_t w0 = 0;  // the first frame at work
  while (w0 < end && states[w0].away) ++w0;
  if (w0 == end) {  // never at work: all of it is transit
    f.waypoints = flight_piece(plan, states, t0, 0, end, true);
    f.transit_in = static_cast<int>(f.waypoints.size());
    return f;
  }
  std::size_t w1 = end - 1;  // the last frame at work
  while (states[w1].away) --w1;
  // The step in which the mission's last cell became known ends with the UAV turned home, so the
  // trace shows it away; but it made that step's move at work and sensed on arrival. A UAV sent
  // home for its battery is away from the step it was sent: that step is the flight home's.
  if (w1 + 1 < end && t0 + static_cast<int>(w1) + 1 == plan.homing_frame) {
    const auto& a = states[w1];
    const auto& b = states[w1 + 1];
    if (b.airborne && !b.in_transit && (b.pos != a.pos || b.z != a.z)) ++w1;
  }
  if (w0 > 0) {
    f.waypoints = flight_piece(plan, states, t0, 0, w0 + 1, true);
    // Its last waypoint is the arrival at the work's start: the first of the work's own.
    f.transit_in = static_cast<int>(f.waypoints.size()) - 1;
  }
  const auto work = flight_piece(plan, states, t0, w0, w1 + 1, false);
  f.waypoints.insert(f.waypoints.end(), work.begin() + (w0 > 0 ? 1 : 0), work.end());
  if (w1 + 1 < end) {
    const auto home = flight_piece(plan, states, t0, w1, end, true);
    f.waypoints.insert(f.waypoints.end(), home.begin() + 1, home.end());  // [0] ends the work
    f.transit_out = static_cast<int>(home.size()) - 1;
  }
  return f;
}

std::vector<std::vector<FlownSortie>> recorded_sorties(const ExportPlan& plan) {
  std::vector<std::vector<FlownSortie>> out;
  for (std::size_t k = 0; k < plan.states.size(); ++k) {
    auto& sorties = out.emplace_back();
    const auto& states = plan.states[k];
    const int site = k < plan.site_of.size() ? plan.site_of[k] : 0;
    for (std::size_t t = 0; t < states.size(); ++t) {
      const bool before = t > 0 && states[t - 1].airborne;
      if (states[t].airborne && !before) {
        // Airborne from frame 0: taken off in no time; else the step from the frame before.
        sorties.push_back({t == 0 ? 0 : static_cast<int>(t) - 1, -1, site});
      } else if (!states[t].airborne && before && !sorties.empty()) {
        sorties.back().landing = static_cast<int>(t);
      }
    }
  }
  return out;
}

std::vector<Sortie> plan_sorties(const ExportPlan& plan, const std::vector<grid::Cell>& sites,
                                 const std::vector<std::vector<FlownSortie>>& flown_sorties,
                                 std::optional<double> home_z) {
  for (const auto& s : sites) check_site(plan, s);
  std::vector<Sortie> sorties;
  for (std::size_t k = 0; k < plan.uavs.size(); ++k) {
    if (k < flown_sorties.size() && !flown_sorties[k].empty()) {
      for (auto& s : cut_sorties(plan, sites, k, flown_sorties[k])) sorties.push_back(std::move(s));
      continue;
    }
    // The trace's flight; with the mission's own launch sites it flies out from one and home.
    auto flight = compress_flight(plan, plan.states[k], 0);
    const auto& flown = flight.waypoints;
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
      s.waypoints.insert(s.waypoints.end(), flown.begin(), flown.end());
      if (first.grid.z != 2) {  // the plan's start on plane 1 is reached by a descent
        auto& start = s.waypoints[legs_in.size()].grid;
        start.action = WaypointAction::kPlaneChange;
        start.duration = plan.plane_change_steps;
      }
      s.transit_in = static_cast<int>(legs_in.size()) + flight.transit_in;
      s.transit_out = flight.transit_out;
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
      s.transit_in = flight.transit_in;
      s.transit_out = flight.transit_out;
      s.waypoints = std::move(flight.waypoints);
    }
    sorties.push_back(std::move(s));
  }
  for (auto& s : sorties) {
    s.home = home_below(plan, s.site, home_z);
    const double first_z = s.waypoints.empty() ? s.home.z : s.waypoints.front().pose.z;
    if (home_z && s.home.z > first_z + 1e-9) {
      throw ParameterError(
          "launch-height",
          fmt::format("the ground at {} m lies above UAV {}'s first waypoint (Z = {:.4f} m, the "
                      "launch site {},{} on plane 2): a sortie takes off upward to it; give a "
                      "launch site at the ground's height or above",
                      s.home.z, s.uav, first_z, s.site.x, s.site.y));
    }
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
