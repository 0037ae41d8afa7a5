#include "hullinspect/grid/target_search.hpp"

#include "step_choice.hpp"
#include "weighted_relax.hpp"

namespace hullinspect::grid {

void TargetSearch::bind(DistanceService* service) {
  service_ = service;
  target_ = -1;
  touched_.clear();
  dist_ = Grid<int>();
  buckets_.clear();
}

Cell TargetSearch::next_step(Cell from, Cell to) {
  if (from == to) return from;
  // Manhattan distances: the service answers without a search.
  if (!service_->searched()) return service_->next_step(from, to);
  const Grid<std::uint8_t>& allowed = service_->allowed_mask();
  const int target = allowed.index(to);
  if (target != target_) restart(target);
  // Positions on a shortest path from `from` are nearer to the target: settled with it.
  settle(allowed.index(from));
  return detail::step_on_field(from, to, allowed, service_->flight_table(), dist_);
}

void TargetSearch::restart(int target) {
  const Grid<std::uint8_t>& allowed = service_->allowed_mask();
  if (dist_.width() != allowed.width() || dist_.height() != allowed.height()) {
    dist_ = Grid<int>(allowed.width(), allowed.height(), kUnreachable);
    touched_.clear();
    buckets_.assign(static_cast<std::size_t>(service_->flight_table().longest() + 1), {});
  }
  for (const int i : touched_) dist_[i] = kUnreachable;
  touched_.clear();
  for (auto& bucket : buckets_) bucket.clear();
  target_ = target;
  dist_[target] = 0;
  touched_.push_back(target);
  buckets_[0].push_back(target);
  pending_ = 1;
  settled_ = -1;
}

void TargetSearch::settle(int index) {
  // The whole-grid search's order (Dial's buckets), one distance at a time: once the bucket of
  // distance d is done, every position at distance d is final.
  const Grid<std::uint8_t>& allowed = service_->allowed_mask();
  const EdgeSteps& steps = service_->flight_table();
  const std::size_t span = buckets_.size();
  while (dist_[index] > settled_ && pending_ > 0) {
    const int d = settled_ + 1;
    auto& bucket = buckets_[static_cast<std::size_t>(d) % span];
    // Flights of at least one step push into other buckets, so this one only shrinks here.
    for (std::size_t b = 0; b < bucket.size(); ++b) {
      const int i = bucket[b];
      --pending_;
      if (dist_[i] != d) continue;  // settled earlier at a shorter distance
      // A cell that is not allowed can end a path but never lies inside one.
      if (allowed[i] == 0 && d != 0) continue;
      pending_ += detail::relax_flights(i, d, allowed, steps, dist_, buckets_,
                                        [this](int j) { touched_.push_back(j); });
    }
    bucket.clear();
    settled_ = d;
  }
}

}  // namespace hullinspect::grid
