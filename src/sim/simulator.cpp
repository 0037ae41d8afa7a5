#include "hullinspect/sim/simulator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/plural.hpp"
#include "hullinspect/world/standoff_surface.hpp"

namespace hullinspect::sim {

Simulator::Simulator(const world::HullMask& hull, const world::Instance& instance,
                     const world::MissionParams& params)
    : Simulator(hull, instance, params, world::start_cells(params, hull)) {}

Simulator::Simulator(const world::HullMask& hull, const world::Instance& instance,
                     const world::MissionParams& params, std::span<const grid::Cell> starts)
    : hull_(hull),
      truth_(instance.truth),
      params_(params),
      starts_(starts.begin(), starts.end()),
      uz_(params.plane_change_steps()),
      flights_(world::neighbour_flights(hull, params)) {
  const int n = params.uavs;
  if (starts.size() != static_cast<std::size_t>(n)) {
    throw LogicError(fmt::format("{} start cells for {}", starts.size(), plural(n, "UAV")));
  }
  for (const auto& c : starts) {
    if (no_fly(c)) {
      throw LogicError(fmt::format("a UAV starts on the no-fly position ({}, {})", c.x, c.y));
    }
  }
  reach_ = world::compute_reachability(hull, params.no_fly.get(), params.s1, params.s2, starts);
  map_ = grid::Grid<std::int8_t>(hull.width(), hull.height(), kNotHull);
  seen_ = grid::Grid<std::uint8_t>(hull.width(), hull.height(), 0);
  counted_ = grid::Grid<std::uint8_t>(hull.width(), hull.height(), 0);
  for (int i : hull.cells()) {
    map_[i] = instance.prior[i] == 1 ? kCorrosionSeen : kUnknown;
    // Only cells that can reach their final state count (docs/model.md): a corroded cell needs a
    // z = 1 footprint, a clean one either plane's.
    const std::uint8_t need = truth_[i] == 1 ? world::kReachZ1 : world::kReachZ2;
    if ((reach_.reach[i] & need) == 0) continue;
    counted_[i] = 1;
    ++hull_cells_;
    if (truth_[i] == 1) ++corroded_;
  }

  uavs_.resize(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    uavs_[static_cast<std::size_t>(k)] =
        UavState{starts[static_cast<std::size_t>(k)], params.start_z, 0, false};
  }
  legs_ = world::plan_launch_legs(params, reach_, starts, flights_.plane[1]);
  battery_ = world::battery_steps(params);
  world::check_endurance_reaches(params, hull, reach_, legs_);
  if (!legs_.empty()) {
    // Each UAV waits on the ground (transfer, take-off) at its site, flies out on plane 2 and
    // descends when the mission starts on plane 1: the reverse of its flight home from the start.
    away_path_.resize(static_cast<std::size_t>(n));
    away_next_.assign(static_cast<std::size_t>(n), 0);
    landed_end_.assign(static_cast<std::size_t>(n), 0);
    out_begin_.assign(static_cast<std::size_t>(n), 0);
    for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k) {
      auto out = legs_.path_home(static_cast<int>(k), starts[k]);
      std::reverse(out.begin(), out.end());
      const grid::Cell site = out.empty() ? starts[k] : out.front();
      auto& path = away_path_[k];
      path.assign(static_cast<std::size_t>(legs_.transfer_steps + legs_.takeoff_steps),
                  AwayStep{site});
      for (std::size_t i = 1; i < out.size(); ++i) path.push_back(AwayStep{out[i]});
      path.push_back(AwayStep{starts[k]});
      path.resize(static_cast<std::size_t>(legs_.outbound[k]), AwayStep{starts[k]});
      if (!path.empty()) path.back().z = static_cast<std::int8_t>(params.start_z);
      uavs_[k].pos = site;
      uavs_[k].z = path.empty() ? params.start_z : 2;
      uavs_[k].away_left = static_cast<int>(path.size());
      uavs_[k].airborne = path.empty();
    }
  }
  if (battery_.limited) {
    for (auto& u : uavs_) u.battery_left = battery_.endurance;
  }
  fail_time_.assign(static_cast<std::size_t>(n), -1);
  applied_.assign(static_cast<std::size_t>(n), Action::kHover);
  previous_.resize(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k)
    previous_[static_cast<std::size_t>(k)] = uavs_[static_cast<std::size_t>(k)].pos;

  const int s = std::max(params.s1, params.s2);
  log_.readings_.reserve(static_cast<std::size_t>(n) * s * s);
  log_.begin_.assign(static_cast<std::size_t>(n) + 1, 0);
  changed_.reserve(static_cast<std::size_t>(n) * s * s);

  result_.hull_cells = hull_cells_;
  result_.corroded_cells = corroded_;
  result_.unreachable_cells = reach_.unreachable_z1;
  result_.unreachable_z2_cells = reach_.unreachable_z2;
  result_.uavs.assign(static_cast<std::size_t>(n), UavCounters{});
  for (std::size_t k = 0; k < legs_.site_of.size(); ++k) {
    result_.uavs[k].launch_site = legs_.site_of[k];
    if (battery_.limited) result_.uavs[k].min_battery = battery_.endurance;
    // Take-off and transfer of no time from a site on the start cell: airborne from t = 0.
    if (uavs_[k].airborne) result_.uavs[k].sorties.push_back({0, -1, legs_.site_of[k]});
  }
  const auto series_capacity = static_cast<std::size_t>(std::min(params.time_limit, 1 << 20)) + 1;
  result_.inspected_series.reserve(series_capacity);
  result_.known_series.reserve(series_capacity);

  sense_all();
  record_metrics();
  check_separation();
}

void Simulator::fail_uav_at(int uav, int from_time) {
  if (uav < 0 || uav >= static_cast<int>(uavs_.size())) {
    throw LogicError(fmt::format("fail_uav_at: no UAV {} in a fleet of {}", uav, uavs_.size()));
  }
  fail_time_[static_cast<std::size_t>(uav)] = from_time;
}

void Simulator::step(std::span<const Action> actions) {
  step(actions, {});
}

void Simulator::step(std::span<const Action> actions, std::span<const std::uint8_t> away_orders) {
  if (finished())
    throw LogicError(fmt::format("step() called on a finished mission (t = {})", time_));
  if (actions.size() != uavs_.size()) {
    throw LogicError(
        fmt::format("planner returned {} actions for {} UAVs", actions.size(), uavs_.size()));
  }
  if (params_.separation > 0) {
    for (std::size_t k = 0; k < uavs_.size(); ++k) previous_[k] = uavs_[k].pos;
  }
  for (std::size_t k = 0; k < uavs_.size(); ++k) {
    UavState& u = uavs_[k];
    UavCounters& count = result_.uavs[k];
    // Airborne with an empty battery: a crash, which fails the UAV as a failure does.
    const bool crash = !u.failed && u.airborne && u.battery_left == 0;
    if (crash || (!u.failed && fail_time_[k] >= 0 && time_ >= fail_time_[k])) {
      u.failed = true;
      count.failed_at = time_;
      count.battery_crash = crash;
      if (crash) ++result_.battery_crashes;
      ++failed_;
    }
    applied_[k] = Action::kHover;
    if (u.failed) continue;
    const bool was_airborne = u.airborne;
    if (u.away_left > 0) {
      const std::uint8_t order = k < away_orders.size() ? away_orders[k] : kGo;
      if (order == kHold) {
        // Waiting on the ground, or hovering where it is: the leg resumes next step.
        ++count.steps_away;
      } else {
        if (order == kTurnBack) turn_back(k);
        if (order >= kDetour) detour(k, moved(u.pos, static_cast<Action>(order - kDetour)));
        advance_away(k);
      }
      use_battery(k, was_airborne);
      continue;
    }
    if (!u.airborne) continue;  // landed at its site for good
    if (u.flight_left > 0) {
      // Still flying to the neighbour it moved to: a step on its plane without sensing.
      --u.flight_left;
      ++(u.z == 1 ? count.steps_z1 : count.steps_z2);
      use_battery(k, was_airborne);
      continue;
    }
    if (u.in_transit()) {
      ++count.steps_transit;
      if (--u.transit_left == 0) u.z = 3 - u.z;
      use_battery(k, was_airborne);
      continue;
    }
    const Action a = actions[k];
    applied_[k] = a;
    switch (a) {
      case Action::kHover:
        ++count.hovers;
        break;
      case Action::kChangePlane:
        ++count.plane_changes;
        ++count.steps_transit;
        u.transit_left = uz_ - 1;
        if (u.transit_left == 0) u.z = 3 - u.z;
        break;
      default: {
        const grid::Cell next = moved(u.pos, a, map_.width(), map_.height(), flights_.plane[0]);
        if (!map_.contains(next)) {
          throw LogicError(
              fmt::format("UAV {} at ({}, {}) was told to move {} off the {} × {} grid at "
                          "t = {}",
                          k, u.pos.x, u.pos.y, to_string(a), map_.width(), map_.height(), time_));
        }
        if (no_fly(next)) {
          throw LogicError(
              fmt::format("UAV {} at ({}, {}) was told to move {} onto the no-fly "
                          "position ({}, {}) at t = {}",
                          k, u.pos.x, u.pos.y, to_string(a), next.x, next.y, time_));
        }
        u.flight_left = flights_.between(u.pos, next, u.z) - 1;
        u.pos = next;
        ++count.moves;
      }
    }
    // A UAV is away only before the actions (handled above), so this is "not changing plane".
    if (u.transit_left == 0) ++(u.z == 1 ? count.steps_z1 : count.steps_z2);
    use_battery(k, was_airborne);
  }
  ++time_;
  sense_all();
  record_metrics();
  check_separation();
}

// Every pair once per step: n(n − 1)/2 comparisons, nothing allocated; nothing at all when D = 0.
// Only airborne UAVs count (a failed one still occupies its cell): a UAV on the ground at its
// launch site has landed, and several may stand on one site.
void Simulator::check_separation() {
  const int d = params_.separation;
  if (d <= 0 || uavs_.size() < 2) return;
  int smallest = result_.min_separation.value_or(std::numeric_limits<int>::max());
  bool measured = false;
  for (std::size_t a = 0; a < uavs_.size(); ++a) {
    if (!uavs_[a].airborne) continue;
    const grid::Cell pa = uavs_[a].pos;
    for (std::size_t b = a + 1; b < uavs_.size(); ++b) {
      if (!uavs_[b].airborne) continue;
      measured = true;
      const grid::Cell pb = uavs_[b].pos;
      int gap = grid::chebyshev(pa, pb);
      // Two UAVs that exchange cells pass through each other: separation 0 for that step.
      if (pa != pb && pa == previous_[b] && pb == previous_[a]) gap = 0;
      smallest = std::min(smallest, gap);
      if (gap >= d) continue;
      ++result_.separation_conflicts;
      if (params_.strict_separation) {
        throw LogicError(fmt::format(
            "separation conflict at t = {}: UAVs {} at ({}, {}) and {} at ({}, {}) are {} apart{}, "
            "less than the separation {}",
            time_, a, pa.x, pa.y, b, pb.x, pb.y, plural(grid::chebyshev(pa, pb), "cell"),
            gap == 0 && pa != pb ? " and exchanged cells" : "", d));
      }
    }
  }
  if (measured) result_.min_separation = smallest;
}

// A step flown (or taken off or landed in) uses one step of battery; the step that ends a swap
// leaves a full one. Records take-offs and landings as sorties.
void Simulator::use_battery(std::size_t k, bool was_airborne) {
  UavState& u = uavs_[k];
  UavCounters& count = result_.uavs[k];
  if (!was_airborne && !u.airborne) return;
  ++count.flight_steps;
  if (!legs_.empty()) {
    if (!was_airborne) count.sorties.push_back({time_, -1, legs_.site_of[k]});
    if (!u.airborne && !count.sorties.empty()) count.sorties.back().landing = time_ + 1;
  }
  if (!battery_.limited) return;
  --u.battery_left;
  if (u.airborne) count.min_battery = std::min(count.min_battery, u.battery_left);
}

void Simulator::advance_away(std::size_t k) {
  UavState& u = uavs_[k];
  const auto& path = away_path_[k];
  std::size_t& next = away_next_[k];
  const AwayStep& s = path[next++];
  u.pos = s.pos;
  u.z = s.z;
  u.airborne = (s.flags & kAirborne) != 0;
  u.away_left = static_cast<int>(path.size() - next);
  ++result_.uavs[k].steps_away;
  if ((s.flags & kSwapped) != 0) {
    u.battery_left = battery_.endurance;
    ++result_.uavs[k].swaps;
  }
  if (homing_ && u.away_left == 0 && !u.airborne) result_.uavs[k].landed_at = time_ + 1;
}

grid::Cell Simulator::append_flight_home(std::size_t k) {
  UavState& u = uavs_[k];
  auto& path = away_path_[k];
  // Climb (finishing a plane change), fly home on plane 2, land and transfer.
  const int total = legs_.homeward_steps(static_cast<int>(k), u.pos, u.z, u.transit_left);
  const auto flight = legs_.path_home(static_cast<int>(k), u.pos);
  const grid::Cell site = flight.empty() ? u.pos : flight.back();
  const int climb =
      total - static_cast<int>(flight.size()) - legs_.takeoff_steps - legs_.transfer_steps;
  const std::size_t begin = path.size();
  // The climb happens where the UAV is: a plane change under way ends, a descent under way is
  // finished and climbed back, each reaching its plane on its last step as a working UAV's plane
  // change does, so the UAV is on plane 2 at this cell before it flies on.
  int z = u.z;
  int change_left = u.transit_left;
  for (int i = 0; i < climb; ++i) {
    if (change_left == 0) change_left = legs_.plane_change_steps;
    if (--change_left == 0) z = 3 - z;
    path.push_back(AwayStep{u.pos, static_cast<std::int8_t>(z)});
  }
  for (const grid::Cell c : flight) path.push_back(AwayStep{c});
  path.resize(begin + static_cast<std::size_t>(total), AwayStep{site});
  if (path.size() > begin) path.back().flags = 0;
  u.transit_left = 0;
  u.flight_left = 0;
  return site;
}

void Simulator::return_for_swap(int uav) {
  if (legs_.empty() || uav < 0 || uav >= static_cast<int>(uavs_.size())) {
    throw LogicError(fmt::format("return_for_swap: no UAV {} with a launch site", uav));
  }
  const auto k = static_cast<std::size_t>(uav);
  UavState& u = uavs_[k];
  if (u.failed || u.away_left > 0) {
    throw LogicError(fmt::format("return_for_swap: UAV {} is {} at t = {}", uav,
                                 u.failed ? "failed" : "already away", time_));
  }
  const grid::Cell resume = u.pos;
  const int resume_z = u.transit_left > 0 ? 3 - u.z : u.z;
  auto& path = away_path_[k];
  path.clear();
  const grid::Cell site = append_flight_home(k);
  if (path.empty()) path.push_back(AwayStep{site, 2, 0});  // landed where it was: one step down
  landed_end_[k] = path.size();
  path.resize(path.size() + static_cast<std::size_t>(battery_.swap), AwayStep{site, 2, 0});
  path.back().flags = kSwapped;
  out_begin_[k] = path.size();
  // The way out: transfer and take-off at the site, the flight to `resume`, the descent.
  path.resize(path.size() + static_cast<std::size_t>(legs_.transfer_steps + legs_.takeoff_steps),
              AwayStep{site});
  auto out = legs_.path_home(uav, resume);
  std::reverse(out.begin(), out.end());
  for (std::size_t i = 1; i < out.size(); ++i) path.push_back(AwayStep{out[i]});
  if (!out.empty()) path.push_back(AwayStep{resume});
  if (resume_z == 1) {
    path.resize(path.size() + static_cast<std::size_t>(legs_.plane_change_steps), AwayStep{resume});
  }
  if (path.size() == out_begin_[k]) path.push_back(AwayStep{resume});  // take off on the spot
  path.back().z = static_cast<std::int8_t>(resume_z);
  away_next_[k] = 0;
  u.away_left = static_cast<int>(path.size());
}

std::vector<Simulator::AwayStep> Simulator::flight_back(std::size_t k) const {
  // From the cell before the one it is on back along the cells it has flown since its take-off,
  // and down at the site.
  const auto& path = away_path_[k];
  const std::size_t b = out_begin_[k];
  std::vector<AwayStep> home;
  for (std::size_t i = away_next_[k]; i-- > b + 1;) home.push_back(AwayStep{path[i - 1].pos});
  home.push_back(AwayStep{path[b].pos, 2, 0});
  return home;
}

void Simulator::turn_back(std::size_t k) {
  auto& path = away_path_[k];
  std::vector<AwayStep> legs = flight_back(k);
  // Then the same take-off and flight out again.
  const auto out = path.begin() + static_cast<std::ptrdiff_t>(out_begin_[k]);
  landed_end_[k] = out_begin_[k] = legs.size();
  legs.insert(legs.end(), out, path.end());
  path = std::move(legs);
  away_next_[k] = 0;
  uavs_[k].away_left = static_cast<int>(path.size());
}

void Simulator::detour(std::size_t k, grid::Cell c) {
  auto& path = away_path_[k];
  const std::vector<AwayStep> after(path.begin() + static_cast<std::ptrdiff_t>(landed_end_[k]),
                                    path.end());
  const std::size_t ground = out_begin_[k] - landed_end_[k];
  UavState& u = uavs_[k];
  const grid::Cell here = u.pos;
  path.assign(1, AwayStep{c});
  u.pos = c;
  append_flight_home(k);
  u.pos = here;  // advance_away moves it
  landed_end_[k] = path.size();
  out_begin_[k] = landed_end_[k] + ground;
  path.insert(path.end(), after.begin(), after.end());
  away_next_[k] = 0;
  u.away_left = static_cast<int>(path.size());
}

void Simulator::next_away_moves(std::span<AwayMove> out) const {
  for (std::size_t k = 0; k < uavs_.size() && k < out.size(); ++k) {
    const UavState& u = uavs_[k];
    if (u.failed || u.away_left == 0) continue;
    const auto& path = away_path_[k];
    const std::size_t next = away_next_[k];
    const AwayStep& s = path[next];
    AwayMove& m = out[k];
    m.pos = s.pos;
    m.airborne = (s.flags & kAirborne) != 0;
    m.leg = next < landed_end_[k]  ? AwayMove::Leg::kHome
            : next < out_begin_[k] ? AwayMove::Leg::kGround
                                   : AwayMove::Leg::kOut;
    m.site = legs_.site_of[k];
    m.back = s.pos;
    m.back_airborne = m.airborne;
    if (m.leg == AwayMove::Leg::kOut && u.airborne) {
      const std::size_t b = out_begin_[k];
      m.back = next >= b + 2 ? path[next - 2].pos : path[b].pos;
      m.back_airborne = next >= b + 2;
    }
  }
}

void Simulator::start_homing() {
  homing_ = true;
  for (std::size_t k = 0; k < uavs_.size(); ++k) {
    UavState& u = uavs_[k];
    if (u.failed) continue;
    auto& path = away_path_[k];
    const std::size_t next = away_next_[k];
    if (u.away_left > 0 && next < landed_end_[k]) {
      // Flying home for a swap: it lands and stays.
      path.resize(landed_end_[k]);
    } else if (u.away_left > 0 && next <= out_begin_[k]) {
      path.resize(next);  // on the ground: it stays
    } else if (u.away_left > 0) {
      // On its way out: it turns back along the positions it has flown, to the ground.
      path = flight_back(k);
      away_next_[k] = 0;
    } else {
      path.clear();
      append_flight_home(k);
      away_next_[k] = 0;
    }
    landed_end_[k] = out_begin_[k] = path.size();
    u.away_left = static_cast<int>(path.size() - away_next_[k]);
    if (u.away_left == 0) {
      u.airborne = false;
      result_.uavs[k].landed_at = time_;
    }
  }
}

void Simulator::sense_all() {
  log_.readings_.clear();
  changed_.clear();
  for (std::size_t k = 0; k < uavs_.size(); ++k) {
    log_.begin_[k] = static_cast<int>(log_.readings_.size());
    const UavState& u = uavs_[k];
    if (!u.failed && !u.in_transit()) sense(static_cast<int>(k));
  }
  log_.begin_[uavs_.size()] = static_cast<int>(log_.readings_.size());
}

void Simulator::sense(int uav) {
  const UavState& u = uavs_[static_cast<std::size_t>(uav)];
  const int half = params_.half_side(u.z);
  const int x0 = std::max(0, u.pos.x - half);
  const int x1 = std::min(map_.width() - 1, u.pos.x + half);
  const int y0 = std::max(0, u.pos.y - half);
  const int y1 = std::min(map_.height() - 1, u.pos.y + half);
  const std::uint8_t seen_bit = u.z == 2 ? kSeenAtZ2 : kSeenAtZ1;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const int i = map_.index(x, y);
      const std::int8_t before = map_[i];
      if (before == kNotHull) continue;
      const bool corroded = truth_[i] == 1;
      Reading r{i, kClean, 0};
      if (seen_[i] == 0) r.events |= kEventFirstSeen;
      std::int8_t after = before;
      if (!corroded) {
        after = kClean;
      } else if (u.z == 1) {
        after = kInspected;
        r.value = kInspected;
      } else {
        r.value = kCorrosionSeen;
        if (before != kInspected) after = kCorrosionSeen;
        if ((seen_[i] & kSeenAtZ2) == 0) {
          r.events |= kEventDetection;
          ++result_.detections;
        }
      }
      seen_[i] |= seen_bit;
      if (after != before) {
        if (after == kInspected) {
          ++inspected_;
          r.events |= kEventInspection;
        }
        if ((after == kClean || after == kInspected) && before != kClean && before != kInspected &&
            counted_[i] != 0) {
          ++known_;
        }
        map_[i] = after;
        changed_.push_back(i);
      } else if ((r.events & kEventDetection) == 0) {
        r.events |= kEventRedundant;
        ++result_.redundant_observations;
      }
      ++result_.observations;
      log_.readings_.push_back(r);
    }
  }
}

void Simulator::record_metrics() {
  result_.inspected_series.push_back(inspected_);
  result_.known_series.push_back(known_);
  if (!result_.t_c && inspected_ == corroded_) result_.t_c = time_;
  if (result_.t_m || known_ != hull_cells_) return;
  if (!legs_.empty()) {
    // With launch sites, T_m is the time the last working UAV has landed (docs/model.md).
    if (!homing_) start_homing();
    for (const UavState& u : uavs_) {
      if (!u.failed && u.away_left > 0) return;
    }
    homing_ = false;
  }
  result_.t_m = time_;
}

double Simulator::c_percent() const {
  return corroded_ == 0 ? 100.0 : 100.0 * inspected_ / corroded_;
}

double Simulator::m_percent() const {
  return hull_cells_ == 0 ? 100.0 : 100.0 * known_ / hull_cells_;
}

MissionResult Simulator::result() const {
  MissionResult r = result_;
  r.steps = time_;
  r.complete = complete() && r.t_m.has_value();
  r.failed_uavs = failed_;
  return r;
}

}  // namespace hullinspect::sim
