#include "max_flow.hpp"

#include <algorithm>
#include <limits>

namespace hullinspect::tsp::detail {

namespace {
constexpr double kTiny = 1e-9;  // residual capacity below this counts as none
}

void FlowGraph::reset(int n) {
  n_ = n;
  from_.clear();
  to_.clear();
  capacity_.clear();
}

void FlowGraph::add_edge(int u, int v, double capacity) {
  from_.push_back(u);
  to_.push_back(v);
  capacity_.push_back(capacity);
}

void FlowGraph::build() {
  const auto n = static_cast<std::size_t>(n_);
  start_.assign(n + 1, 0);
  for (std::size_t e = 0; e < from_.size(); ++e) {
    ++start_[static_cast<std::size_t>(from_[e]) + 1];
    ++start_[static_cast<std::size_t>(to_[e]) + 1];
  }
  for (std::size_t v = 0; v < n; ++v) start_[v + 1] += start_[v];
  const auto arcs = static_cast<std::size_t>(start_[n]);
  head_.assign(arcs, 0);
  reverse_.assign(arcs, 0);
  arc_capacity_.assign(arcs, 0.0);
  std::vector<int>& fill = queue_;  // reused as the insertion cursor
  fill.assign(start_.begin(), start_.end() - 1);
  for (std::size_t e = 0; e < from_.size(); ++e) {
    const auto a = static_cast<std::size_t>(fill[static_cast<std::size_t>(from_[e])]++);
    const auto b = static_cast<std::size_t>(fill[static_cast<std::size_t>(to_[e])]++);
    head_[a] = to_[e];
    head_[b] = from_[e];
    reverse_[a] = static_cast<int>(b);
    reverse_[b] = static_cast<int>(a);
    arc_capacity_[a] = capacity_[e];
    arc_capacity_[b] = capacity_[e];
  }
}

double FlowGraph::max_flow(int source, int sink, double enough) {
  const auto n = static_cast<std::size_t>(n_);
  residual_ = arc_capacity_;
  double flow = 0;
  const int marker = std::numeric_limits<int>::max();
  while (true) {
    reached_.assign(n, -1);
    reached_[static_cast<std::size_t>(source)] = marker;
    queue_.assign(1, source);
    for (std::size_t head = 0; head < queue_.size() && reached_[static_cast<std::size_t>(sink)] < 0;
         ++head) {
      const auto a = static_cast<std::size_t>(queue_[head]);
      for (int k = start_[a]; k < start_[a + 1]; ++k) {
        const auto b = static_cast<std::size_t>(head_[static_cast<std::size_t>(k)]);
        if (reached_[b] < 0 && residual_[static_cast<std::size_t>(k)] > kTiny) {
          reached_[b] = k;
          queue_.push_back(static_cast<int>(b));
        }
      }
    }
    if (reached_[static_cast<std::size_t>(sink)] < 0) return flow;
    double push = enough - flow;
    for (int b = sink; b != source;) {
      const auto k = static_cast<std::size_t>(reached_[static_cast<std::size_t>(b)]);
      push = std::min(push, residual_[k]);
      b = head_[static_cast<std::size_t>(reverse_[k])];
    }
    for (int b = sink; b != source;) {
      const auto k = static_cast<std::size_t>(reached_[static_cast<std::size_t>(b)]);
      residual_[k] -= push;
      residual_[static_cast<std::size_t>(reverse_[k])] += push;
      b = head_[static_cast<std::size_t>(reverse_[k])];
    }
    flow += push;
    if (flow >= enough) return flow;
  }
}

}  // namespace hullinspect::tsp::detail
