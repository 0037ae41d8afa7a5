// DistanceService::distances_to: distances from one source to a few targets without a search of
// the whole grid (a segment TSP's end-to-end costs on a large hull with long flights).

#include "hullinspect/grid/distance_service.hpp"

#include "weighted_relax.hpp"

namespace hullinspect::grid {

void DistanceService::distances_to(Cell source, std::span<const Cell> targets, std::span<int> out) {
  if (!searched()) {
    for (std::size_t t = 0; t < targets.size(); ++t) out[t] = manhattan(source, targets[t]);
    return;
  }
  const int s = allowed_.index(source);
  if (!slot_of_.empty() && slot_of_[static_cast<std::size_t>(s)] >= 0) {
    const Grid<int>& field =
        slots_[static_cast<std::size_t>(slot_of_[static_cast<std::size_t>(s)])].field;
    for (std::size_t t = 0; t < targets.size(); ++t) out[t] = field[targets[t]];
    return;
  }
  if (near_.width() != width() || near_.height() != height()) {
    near_ = Grid<int>(width(), height(), kUnreachable);
    target_state_.assign(static_cast<std::size_t>(allowed_.size()), 0);
  }
  int waiting = 0;
  targets_marked_.clear();
  for (const Cell t : targets) {
    const int i = allowed_.index(t);
    if (target_state_[static_cast<std::size_t>(i)] != 0) continue;
    target_state_[static_cast<std::size_t>(i)] = 1;
    targets_marked_.push_back(i);
    ++waiting;
  }
  // The search of search() and search_weighted() (Dial's buckets; one-step flights without a
  // table), ended when the last target is settled: settled distances are final.
  const int span = longest_flight_ + 1;
  buckets_.resize(static_cast<std::size_t>(span));
  for (auto& b : buckets_) b.clear();
  touched_.clear();
  near_[s] = 0;
  touched_.push_back(s);
  buckets_[0].push_back(s);
  std::size_t pending = 1;
  for (int d = 0; pending > 0 && waiting > 0; ++d) {
    auto& bucket = buckets_[static_cast<std::size_t>(d % span)];
    // Flights of at least one step push into other buckets, so this one only shrinks here.
    for (std::size_t b = 0; b < bucket.size() && waiting > 0; ++b) {
      const int i = bucket[b];
      --pending;
      if (near_[i] != d) continue;  // settled earlier at a shorter distance
      std::uint8_t& state = target_state_[static_cast<std::size_t>(i)];
      if (state == 1) {
        state = 2;
        --waiting;
      }
      // A cell that is not allowed can end a path but never lies inside one.
      if (allowed_[i] == 0 && d != 0) continue;
      pending += detail::relax_flights(i, d, allowed_, steps_, near_, buckets_,
                                       [this](int j) { touched_.push_back(j); });
    }
    bucket.clear();
  }
  // A target still waiting was never reached: the search ran out first.
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const int i = allowed_.index(targets[t]);
    out[t] = target_state_[static_cast<std::size_t>(i)] == 2 ? near_[i] : kUnreachable;
  }
  for (const int i : touched_) near_[i] = kUnreachable;
  for (const int i : targets_marked_) target_state_[static_cast<std::size_t>(i)] = 0;
  for (auto& b : buckets_) b.clear();
}

}  // namespace hullinspect::grid
