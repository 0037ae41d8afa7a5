#include "hullinspect/sim/deconfliction.hpp"

#include <algorithm>
#include <cstdlib>

namespace hullinspect::sim {

namespace {

Action move_of(int dx, int dy) {
  if (dx > 0) return Action::kEast;
  if (dx < 0) return Action::kWest;
  if (dy > 0) return Action::kNorth;
  return Action::kSouth;
}

int sign(int v) {
  return (v > 0) - (v < 0);
}

}  // namespace

Deconfliction::Deconfliction(int separation, int uavs, int width, int height,
                             const grid::Grid<std::uint8_t>* no_fly, const grid::EdgeSteps* flights)
    : d_(separation),
      width_(width),
      height_(height),
      no_fly_(no_fly),
      flights_(flights),
      patience_(separation + 1),
      lead_steps_(2 * (separation + 1)) {
  const auto n = static_cast<std::size_t>(uavs);
  away_.resize(n);
  kind_.assign(n, Kind::kWorking);
  desire_.resize(n);
  desire_air_.assign(n, 1);
  next_.resize(n);
  next_air_.assign(n, 1);
  settled_.assign(n, 0);
  rank_.assign(n, 0);
  order_.resize(n);
  waited_.assign(n, 0);
  lead_.assign(n, 0);
  lead_since_.assign(n, 0);
  side_.assign(n, 0);
  orders_.assign(n, Simulator::kGo);
}

// Whether UAV k may end the step on c (airborne or not): on the grid, not a no-fly position, and,
// airborne, at least D from where every settled UAV ends the step airborne and from where every
// unsettled airborne one is now (an unsettled UAV can always stay as it is), and no exchange of
// cells with a settled one. A UAV on the ground conflicts with nobody. `blocker` gets the first
// UAV in the way (−1 for the grid or a no-fly position).
bool Deconfliction::allowed(int k, grid::Cell c, bool airborne, int* blocker) const {
  if (blocker != nullptr) *blocker = -1;
  if (c.x < 0 || c.y < 0 || c.x >= width_ || c.y >= height_) return false;
  if (no_fly_ != nullptr && (*no_fly_)(c.x, c.y) != 0) return false;
  if (!airborne) return true;
  const UavState& me = uavs_[static_cast<std::size_t>(k)];
  for (std::size_t j = 0; j < uavs_.size(); ++j) {
    if (static_cast<int>(j) == k) continue;
    bool clash = false;
    if (settled_[j] != 0) {
      if (next_air_[j] == 0) continue;
      clash =
          grid::chebyshev(c, next_[j]) < d_ || (me.airborne && uavs_[j].airborne && c != me.pos &&
                                                c == uavs_[j].pos && next_[j] == me.pos);
    } else {
      clash = uavs_[j].airborne && grid::chebyshev(c, uavs_[j].pos) < d_;
    }
    if (clash) {
      if (blocker != nullptr) *blocker = static_cast<int>(j);
      return false;
    }
  }
  return true;
}

// Whether UAV k stands within D of the cell a UAV ahead of it in the order wants to enter
// airborne (a move, or a take-off); the first such UAV is the blocker.
bool Deconfliction::in_way(int k, int& blocker) const {
  const grid::Cell here = uavs_[static_cast<std::size_t>(k)].pos;
  int best = -1;
  for (std::size_t j = 0; j < uavs_.size(); ++j) {
    if (static_cast<int>(j) == k || rank_[j] > rank_[static_cast<std::size_t>(k)]) continue;
    if (desire_air_[j] == 0) continue;
    if (desire_[j] == uavs_[j].pos && uavs_[j].airborne) continue;
    if (grid::chebyshev(desire_[j], here) >= d_) continue;
    if (best < 0 || rank_[j] < rank_[static_cast<std::size_t>(best)]) best = static_cast<int>(j);
  }
  blocker = best;
  return best >= 0;
}

bool Deconfliction::flying_home(int j) const {
  const auto uj = static_cast<std::size_t>(j);
  return kind_[uj] == Kind::kAway && uavs_[uj].airborne && away_[uj].leg == AwayMove::Leg::kHome;
}

// A UAV on the ground takes off only when no UAV of its site is flying home to it: landings go
// first, and a take-off never meets a landing head-on on the site's flights.
bool Deconfliction::site_busy(int k) const {
  const int site = away_[static_cast<std::size_t>(k)].site;
  for (std::size_t j = 0; j < uavs_.size(); ++j) {
    if (static_cast<int>(j) != k && flying_home(static_cast<int>(j)) && away_[j].site == site) {
      return true;
    }
  }
  return false;
}

// A side-step out of the blocker's way: across its line of approach (from where it is to here) on
// the UAV's sticky side, then the other side, then straight away from it; a hover when none is
// allowed.
Action Deconfliction::evade(int k, int blocker) {
  const auto uk = static_cast<std::size_t>(k);
  const grid::Cell here = uavs_[uk].pos;
  // The line of approach runs from the cell the blocker wants, or from where it is when it wants
  // this very cell.
  grid::Cell from = desire_[static_cast<std::size_t>(blocker)];
  if (from == here) from = uavs_[static_cast<std::size_t>(blocker)].pos;
  const int vx = here.x - from.x;
  const int vy = here.y - from.y;
  const bool along_x = std::abs(vx) >= std::abs(vy);
  int& side = side_[uk];
  if (side == 0) {
    const int across = along_x ? vy : vx;
    side = across != 0 ? sign(across) : (k % 2 == 0 ? 1 : -1);
  }
  const int away = along_x ? (vx != 0 ? sign(vx) : side) : (vy != 0 ? sign(vy) : side);
  const int dx[3] = {along_x ? 0 : side, along_x ? 0 : -side, along_x ? away : 0};
  const int dy[3] = {along_x ? side : 0, along_x ? -side : 0, along_x ? 0 : away};
  for (int i = 0; i < 3; ++i) {
    const grid::Cell c{here.x + dx[i], here.y + dy[i]};
    if (!allowed(k, c, true)) continue;
    if (i == 1) side = -side;  // keep going the way that was free
    settle(k, c, true);
    return move_of(dx[i], dy[i]);
  }
  settle(k, here, true);
  return Action::kHover;
}

void Deconfliction::settle(int k, grid::Cell c, bool airborne) {
  const auto uk = static_cast<std::size_t>(k);
  next_[uk] = c;
  next_air_[uk] = airborne ? 1 : 0;
  settled_[uk] = 1;
}

// The order's key (lower goes first). UAVs that cannot move settle first. Then the UAVs away at
// their sites that are airborne, those flying home before those flying out (they cannot side-step,
// so the others make way for them). Then the UAVs that lead (held back for `patience_` steps, a
// UAV waiting to take off included), the older lead first: letting a UAV that waited too long go
// first, and for long enough to get past, is what breaks a standoff between two UAVs that want
// each other's cells, and what clears a site for a take-off. Then the working UAVs, and last the
// take-offs, which wait on the ground until the way is clear.
int Deconfliction::key(int k) const {
  const auto uk = static_cast<std::size_t>(k);
  const UavState& u = uavs_[uk];
  if (kind_[uk] == Kind::kFixed) return 0;
  const bool aged = lead_[uk] > 0;
  if (kind_[uk] == Kind::kAway) {
    if (u.airborne) return away_[uk].leg == AwayMove::Leg::kHome ? 1 : 2;
    return aged ? 3 : 5;
  }
  return aged ? 3 : 4;
}

void Deconfliction::adjust(const Simulator& sim, std::span<Action> actions) {
  uavs_ = sim.uavs();
  sim.next_away_moves(away_);
  const int n = static_cast<int>(uavs_.size());
  for (int k = 0; k < n; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    const UavState& u = uavs_[uk];
    orders_[uk] = Simulator::kGo;
    settled_[uk] = 0;
    order_[uk] = k;
    if (!u.failed && u.away_left > 0) {
      kind_[uk] = Kind::kAway;
      desire_[uk] = away_[uk].pos;
      desire_air_[uk] = away_[uk].airborne ? 1 : 0;
      // Staying on the ground concerns nobody.
      if (!u.airborne && !away_[uk].airborne) kind_[uk] = Kind::kFixed;
    } else if (u.failed || u.in_transit() || !u.airborne) {
      kind_[uk] = Kind::kFixed;
      desire_[uk] = u.pos;
      desire_air_[uk] = u.airborne ? 1 : 0;
    } else {
      kind_[uk] = Kind::kWorking;
      desire_[uk] = flights_ == nullptr ? moved(u.pos, actions[uk])
                                        : moved(u.pos, actions[uk], width_, height_, *flights_);
      desire_air_[uk] = 1;
    }
    if (kind_[uk] == Kind::kFixed) {
      lead_[uk] = 0;
    } else if (lead_[uk] == 0 && waited_[uk] >= patience_) {
      lead_[uk] = lead_steps_;
      lead_since_[uk] = step_;
    }
  }
  ++step_;
  std::sort(order_.begin(), order_.end(), [&](int a, int b) {
    const int ka = key(a);
    const int kb = key(b);
    if (ka != kb) return ka < kb;
    const auto ua = static_cast<std::size_t>(a);
    const auto ub = static_cast<std::size_t>(b);
    // Flying home: the emptier battery first.
    if (ka == 1 && uavs_[ua].battery_left != uavs_[ub].battery_left) {
      return uavs_[ua].battery_left < uavs_[ub].battery_left;
    }
    if (ka == 3 && lead_since_[ua] != lead_since_[ub]) return lead_since_[ua] < lead_since_[ub];
    return a < b;
  });
  for (int r = 0; r < n; ++r)
    rank_[static_cast<std::size_t>(order_[static_cast<std::size_t>(r)])] = r;

  for (int k : order_) {
    const auto uk = static_cast<std::size_t>(k);
    switch (kind_[uk]) {
      case Kind::kFixed:
        settle(k, desire_[uk], desire_air_[uk] != 0);
        break;
      case Kind::kAway:
        decide_away(k);
        break;
      case Kind::kWorking:
        decide_working(k, actions);
        break;
    }
    if (lead_[uk] > 0) end_of_lead_step(k);
  }
}

// A lead runs out after `lead_steps_` steps with no other airborne UAV within 2D (the leader has
// got past), at once when its planner wants it to stay where it is (it is not passing anyone), and
// in any case after 4 · `lead_steps_` steps.
void Deconfliction::end_of_lead_step(int k) {
  const auto uk = static_cast<std::size_t>(k);
  const bool staying = kind_[uk] == Kind::kWorking && desire_[uk] == uavs_[uk].pos;
  if (staying || step_ - lead_since_[uk] >= 4LL * lead_steps_) {
    lead_[uk] = 0;
    return;
  }
  for (std::size_t j = 0; j < uavs_.size(); ++j) {
    if (j != uk && uavs_[j].airborne && grid::chebyshev(uavs_[j].pos, uavs_[uk].pos) <= 2 * d_) {
      return;  // still passing
    }
  }
  --lead_[uk];
}

// A UAV away at its site follows its leg when the next step is allowed. Otherwise it holds (on
// the ground, or hovering where it is, which is always allowed); one flying out that a UAV flying
// home has kept waiting for `patience_` steps turns back to its site, so that the two never wait
// for each other head-on; and one flying home that stands in the way of another flying home
// side-steps.
void Deconfliction::decide_away(int k) {
  const auto uk = static_cast<std::size_t>(k);
  const UavState& u = uavs_[uk];
  const AwayMove& m = away_[uk];
  int blocker = -1;
  const bool takeoff = !u.airborne;
  if (!(takeoff && site_busy(k)) && allowed(k, m.pos, m.airborne, &blocker)) {
    settle(k, m.pos, m.airborne);
    waited_[uk] = 0;
    side_[uk] = 0;
    return;
  }
  if (m.leg == AwayMove::Leg::kOut && u.airborne && waited_[uk] >= patience_ && blocker >= 0 &&
      flying_home(blocker) && allowed(k, m.back, m.back_airborne)) {
    settle(k, m.back, m.back_airborne);
    orders_[uk] = Simulator::kTurnBack;
    ++turn_backs_;
    waited_[uk] = 0;
    return;
  }
  // Flying home on plane 2 in the way of a UAV flying home ahead of it in the order (two legs
  // converging on one site): it side-steps as a working UAV does and flies home from there.
  const bool cruising =
      u.airborne && m.airborne && m.leg == AwayMove::Leg::kHome && u.z == 2 && m.pos != u.pos;
  if (cruising && in_way(k, blocker)) {
    const Action a = evade(k, blocker);
    if (a != Action::kHover) {
      orders_[uk] = static_cast<std::uint8_t>(Simulator::kDetour + static_cast<int>(a));
      ++side_steps_;
      ++waited_[uk];
      return;
    }
  }
  settle(k, u.pos, u.airborne);
  orders_[uk] = Simulator::kHold;
  ++held_;
  ++waited_[uk];
}

void Deconfliction::decide_working(int k, std::span<Action> actions) {
  const auto uk = static_cast<std::size_t>(k);
  const grid::Cell here = uavs_[uk].pos;
  const grid::Cell want = desire_[uk];
  int blocker = -1;
  if (in_way(k, blocker)) {
    // Leave by the planner's own move when it clears the way; otherwise side-step.
    const grid::Cell threat = desire_[static_cast<std::size_t>(blocker)];
    if (want != here && grid::chebyshev(want, threat) >= d_ && allowed(k, want, true)) {
      settle(k, want, true);
      waited_[uk] = 0;
      return;
    }
    const Action a = evade(k, blocker);
    if (a != actions[uk]) {
      ++(a == Action::kHover ? held_ : side_steps_);
      ++waited_[uk];
    }
    actions[uk] = a;
    return;
  }
  side_[uk] = 0;
  if (want == here || allowed(k, want, true)) {
    settle(k, want, true);
    waited_[uk] = 0;
    return;
  }
  settle(k, here, true);
  actions[uk] = Action::kHover;
  ++held_;
  ++waited_[uk];
}

}  // namespace hullinspect::sim
