#include "hullinspect/grid/distance_service.hpp"

#include <algorithm>
#include <utility>

#include "step_choice.hpp"
#include "weighted_relax.hpp"

namespace hullinspect::grid {

DistanceService::DistanceService(int width, int height)
    : allowed_(width, height, std::uint8_t{1}) {}

DistanceService::DistanceService(Grid<std::uint8_t> allowed, int cached_fields)
    : allowed_(std::move(allowed)) {
  for (std::uint8_t a : allowed_.values()) no_fly_count_ += a == 0 ? 1 : 0;
  slots_.resize(static_cast<std::size_t>(std::max(1, cached_fields)));
  slot_of_.assign(static_cast<std::size_t>(allowed_.size()), -1);
}

DistanceService::DistanceService(Grid<std::uint8_t> allowed, EdgeSteps steps, int cached_fields)
    : DistanceService(std::move(allowed), cached_fields) {
  steps_ = std::move(steps);
  longest_flight_ = steps_.longest();
}

int DistanceService::distance(Cell a, Cell b) {
  if (!searched()) return manhattan(a, b);
  return cached_field(allowed_.index(b))[a];
}

const Grid<int>& DistanceService::field(Cell source) {
  return cached_field(allowed_.index(source));
}

const Grid<int>& DistanceService::cached_field(int source) {
  ++clock_;
  if (slot_of_.empty()) slot_of_.assign(static_cast<std::size_t>(allowed_.size()), -1);
  if (slots_.empty()) slots_.resize(1);
  const int known = slot_of_[static_cast<std::size_t>(source)];
  if (known >= 0) {
    Slot& slot = slots_[static_cast<std::size_t>(known)];
    slot.last_used = clock_;
    return slot.field;
  }
  // Least recently used slot (an unused one has last_used 0 and wins; ties: lowest index).
  std::size_t victim = 0;
  for (std::size_t s = 1; s < slots_.size(); ++s) {
    if (slots_[s].last_used < slots_[victim].last_used) victim = s;
  }
  Slot& slot = slots_[victim];
  if (slot.source >= 0) slot_of_[static_cast<std::size_t>(slot.source)] = -1;
  slot.source = source;
  slot.last_used = clock_;
  slot_of_[static_cast<std::size_t>(source)] = static_cast<int>(victim);
  Grid<int>& out = slot.field;
  if (out.width() != width() || out.height() != height()) out = Grid<int>(width(), height());
  ++searches_;
  if (!searched()) {
    const Cell s = allowed_.cell(source);
    for (int y = 0; y < height(); ++y) {
      for (int x = 0; x < width(); ++x) out(x, y) = manhattan(s, Cell{x, y});
    }
    return out;
  }
  out.fill(kUnreachable);
  scratch_.queue.resize(static_cast<std::size_t>(allowed_.size()));
  out[source] = 0;
  scratch_.queue[0] = source;
  if (has_long_flights()) {
    search_weighted(out, 1);
  } else {
    search(out, 1);
  }
  return out;
}

void DistanceService::search(Grid<int>& out, std::size_t seeds) {
  const int w = width();
  const int h = height();
  auto& queue = scratch_.queue;
  std::size_t head = 0;
  std::size_t tail = seeds;
  while (head < tail) {
    const int i = queue[head++];
    const int here = out[i];
    // A cell that is not allowed can end a path but never lies inside one.
    if (allowed_[i] == 0 && here != 0) continue;
    const Cell at{i % w, i / w};
    for (int d = 0; d < 4; ++d) {
      const Cell next = neighbour(at, d, w, h, steps_);
      if (next == kNoCell) continue;
      const int j = next.y * w + next.x;
      if (out[j] <= here + 1) continue;
      out[j] = here + 1;
      queue[tail++] = j;
    }
  }
}

void DistanceService::search_weighted(Grid<int>& out, std::size_t seeds) {
  // Every flight takes 1 … longest steps, so the distances waiting to be settled span fewer than
  // longest + 1 values: one bucket per value modulo that.
  const int span = longest_flight_ + 1;
  buckets_.resize(static_cast<std::size_t>(span));
  for (auto& b : buckets_) b.clear();
  std::size_t pending = seeds;
  for (std::size_t s = 0; s < seeds; ++s) buckets_[0].push_back(scratch_.queue[s]);
  for (int d = 0; pending > 0; ++d) {
    auto& bucket = buckets_[static_cast<std::size_t>(d % span)];
    // Flights of at least one step push into other buckets, so this one only shrinks here.
    for (std::size_t b = 0; b < bucket.size(); ++b) {
      const int i = bucket[b];
      --pending;
      if (out[i] != d) continue;  // settled earlier at a shorter distance
      // A cell that is not allowed can end a path but never lies inside one.
      if (allowed_[i] == 0 && d != 0) continue;
      pending += detail::relax_flights(i, d, allowed_, steps_, out, buckets_, [](int) {});
    }
    bucket.clear();
  }
}

Cell DistanceService::next_step(Cell from, Cell to) {
  if (from == to) return from;
  if (!searched()) {
    return to.x != from.x ? Cell{from.x + (to.x > from.x ? 1 : -1), from.y}
                          : Cell{from.x, from.y + (to.y > from.y ? 1 : -1)};
  }
  return detail::step_on_field(from, to, allowed_, steps_, cached_field(allowed_.index(to)));
}

bool DistanceService::append_path(Cell from, Cell to, std::vector<Cell>& out) {
  Cell at = from;
  while (at != to) {
    const Cell next = next_step(at, to);
    if (next == at) return false;
    out.push_back(next);
    at = next;
  }
  return true;
}

void DistanceService::distances_from(const Grid<std::uint8_t>& sources, Grid<int>& out) {
  if (!searched()) {
    manhattan_distance_transform(sources, out);
    return;
  }
  if (out.width() != width() || out.height() != height()) out = Grid<int>(width(), height());
  out.fill(kUnreachable);
  scratch_.queue.resize(static_cast<std::size_t>(allowed_.size()));
  std::size_t seeds = 0;
  for (int i = 0; i < sources.size(); ++i) {
    if (sources[i] == 0) continue;
    out[i] = 0;
    scratch_.queue[seeds++] = i;
  }
  if (has_long_flights()) {
    search_weighted(out, seeds);
  } else {
    search(out, seeds);
  }
}

Cell DistanceService::viewpoint(Cell c, int half) {
  if (allowed(c)) return c;
  Cell best = kNoCell;
  int best_distance = kUnreachable;
  for (int y = std::max(0, c.y - half); y <= std::min(height() - 1, c.y + half); ++y) {
    for (int x = std::max(0, c.x - half); x <= std::min(width() - 1, c.x + half); ++x) {
      const int d = manhattan(c, Cell{x, y});
      if (allowed_(x, y) == 0 || d >= best_distance) continue;
      best_distance = d;
      best = {x, y};
    }
  }
  return best;
}

void manhattan_distance_transform(const Grid<std::uint8_t>& sources, Grid<int>& out) {
  const int w = sources.width();
  const int h = sources.height();
  if (out.width() != w || out.height() != h) out = Grid<int>(w, h);
  // kUnreachable + 1 cannot overflow (kUnreachable = INT_MAX / 4), so no special case is needed.
  constexpr int kFar = kUnreachable;
  const std::uint8_t* src = sources.values().data();
  int* d = out.values().data();
  // Forward pass, row by row from the bottom: nearest source below (a column-wise step the compiler
  // can vectorise), then to the left (a running scan along the row).
  for (int y = 0; y < h; ++y) {
    int* row = d + static_cast<std::ptrdiff_t>(y) * w;
    const std::uint8_t* s = src + static_cast<std::ptrdiff_t>(y) * w;
    if (y == 0) {
      for (int x = 0; x < w; ++x) row[x] = s[x] ? 0 : kFar;
    } else {
      const int* below = row - w;
      for (int x = 0; x < w; ++x) row[x] = s[x] ? 0 : below[x] + 1;
    }
    for (int x = 1; x < w; ++x) row[x] = std::min(row[x], row[x - 1] + 1);
  }
  // Backward pass from the top: above, then to the right. Two passes are exact for the city-block
  // metric: a shortest path to a source can be ordered as one monotone run per pass.
  for (int y = h - 1; y >= 0; --y) {
    int* row = d + static_cast<std::ptrdiff_t>(y) * w;
    if (y + 1 < h) {
      const int* above = row + w;
      for (int x = 0; x < w; ++x) row[x] = std::min(row[x], above[x] + 1);
    }
    for (int x = w - 2; x >= 0; --x) row[x] = std::min(row[x], row[x + 1] + 1);
    for (int x = 0; x < w; ++x) row[x] = std::min(row[x], kFar);
  }
}

}  // namespace hullinspect::grid
