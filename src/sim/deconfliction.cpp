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
      patience_(separation + 1) {
  const auto n = static_cast<std::size_t>(uavs);
  desire_.resize(n);
  next_.resize(n);
  settled_.assign(n, 0);
  rank_.assign(n, 0);
  order_.resize(n);
  waited_.assign(n, 0);
  side_.assign(n, 0);
}

// Whether UAV k may end the step on c: on the grid, not a no-fly position, at least D from where
// every settled UAV ends the step and from where every unsettled one is now (an unsettled UAV can
// always stay put), and no exchange of cells with a settled one.
bool Deconfliction::allowed(int k, grid::Cell c) const {
  if (c.x < 0 || c.y < 0 || c.x >= width_ || c.y >= height_) return false;
  if (no_fly_ != nullptr && (*no_fly_)(c.x, c.y) != 0) return false;
  const grid::Cell here = uavs_[static_cast<std::size_t>(k)].pos;
  for (std::size_t j = 0; j < uavs_.size(); ++j) {
    if (static_cast<int>(j) == k) continue;
    if (settled_[j] != 0) {
      if (grid::chebyshev(c, next_[j]) < d_) return false;
      if (c != here && c == uavs_[j].pos && next_[j] == here) return false;
    } else if (grid::chebyshev(c, uavs_[j].pos) < d_) {
      return false;
    }
  }
  return true;
}

// Whether UAV k stands within D of the cell a UAV ahead of it in the order wants to enter; the
// first such UAV is the blocker.
bool Deconfliction::in_way(int k, int& blocker) const {
  const grid::Cell here = uavs_[static_cast<std::size_t>(k)].pos;
  int best = -1;
  for (std::size_t j = 0; j < uavs_.size(); ++j) {
    if (static_cast<int>(j) == k || rank_[j] > rank_[static_cast<std::size_t>(k)]) continue;
    if (desire_[j] == uavs_[j].pos) continue;
    if (grid::chebyshev(desire_[j], here) >= d_) continue;
    if (best < 0 || rank_[j] < rank_[static_cast<std::size_t>(best)]) best = static_cast<int>(j);
  }
  blocker = best;
  return best >= 0;
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
    if (!allowed(k, c)) continue;
    if (i == 1) side = -side;  // keep going the way that was free
    settle(k, c);
    return move_of(dx[i], dy[i]);
  }
  settle(k, here);
  return Action::kHover;
}

void Deconfliction::settle(int k, grid::Cell c) {
  next_[static_cast<std::size_t>(k)] = c;
  settled_[static_cast<std::size_t>(k)] = 1;
}

void Deconfliction::adjust(std::span<const UavState> uavs, std::span<Action> actions) {
  uavs_ = uavs;
  const int n = static_cast<int>(uavs.size());
  for (int k = 0; k < n; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    const UavState& u = uavs[uk];
    const bool fixed = u.failed || u.in_transit();
    desire_[uk] = fixed                 ? u.pos
                  : flights_ == nullptr ? moved(u.pos, actions[uk])
                                        : moved(u.pos, actions[uk], width_, height_, *flights_);
    settled_[uk] = 0;
    order_[uk] = k;
  }
  // UAVs that cannot move settle first; then those held back for `patience_` steps or more (the
  // longest-waiting first), then by index. Letting a UAV that waited too long go first is what
  // breaks a standoff between two UAVs that want each other's cells.
  auto key = [&](int k) {
    const UavState& u = uavs[static_cast<std::size_t>(k)];
    if (u.failed || u.in_transit()) return 0;
    const int w = waited_[static_cast<std::size_t>(k)];
    return w >= patience_ ? 1 : 2;
  };
  std::sort(order_.begin(), order_.end(), [&](int a, int b) {
    const int ka = key(a);
    const int kb = key(b);
    if (ka != kb) return ka < kb;
    if (ka == 1 && waited_[static_cast<std::size_t>(a)] != waited_[static_cast<std::size_t>(b)]) {
      return waited_[static_cast<std::size_t>(a)] > waited_[static_cast<std::size_t>(b)];
    }
    return a < b;
  });
  for (int r = 0; r < n; ++r)
    rank_[static_cast<std::size_t>(order_[static_cast<std::size_t>(r)])] = r;

  for (int k : order_) {
    const auto uk = static_cast<std::size_t>(k);
    const UavState& u = uavs[uk];
    if (u.failed || u.in_transit()) {
      settle(k, u.pos);
      continue;
    }
    const grid::Cell here = u.pos;
    const grid::Cell want = desire_[uk];
    int blocker = -1;
    if (in_way(k, blocker)) {
      // Leave by the planner's own move when it clears the way; otherwise side-step.
      const grid::Cell threat = desire_[static_cast<std::size_t>(blocker)];
      if (want != here && grid::chebyshev(want, threat) >= d_ && allowed(k, want)) {
        settle(k, want);
        waited_[uk] = 0;
        continue;
      }
      const Action a = evade(k, blocker);
      if (a != actions[uk]) {
        ++(a == Action::kHover ? held_ : side_steps_);
        ++waited_[uk];
      }
      actions[uk] = a;
      continue;
    }
    side_[uk] = 0;
    if (want == here) {
      settle(k, here);
      waited_[uk] = 0;
      continue;
    }
    if (allowed(k, want)) {
      settle(k, want);
      waited_[uk] = 0;
      continue;
    }
    settle(k, here);
    actions[uk] = Action::kHover;
    ++held_;
    ++waited_[uk];
  }
}

}  // namespace hullinspect::sim
