#include "darp_workspace.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hullinspect/grid/distance_service.hpp"

namespace hullinspect::partition::detail {

namespace {
// Evaluation of a UAV at its own start cell: nothing can undercut it, so start cells never move.
constexpr float kStartValue = -1e30f;
// Fairness multipliers are kept within e^kMaxFairSpread of the largest: far beyond any ratio that
// matters, and it keeps a UAV that can never reach its share from drifting without bound.
constexpr double kMaxFairSpread = 64.0;
// One fairness step changes a multiplier by at most e^±kMaxFairStep (≈ ±10 %): a UAV far from its
// share (say five times too large) would otherwise swing every ratio at once and the regions of
// nearby starts would trade the whole hull back and forth.
constexpr double kMaxFairStep = 0.1;
// Distance-transform cell states in the padded grid.
constexpr int kBlocked = -2;
constexpr int kUnreached = std::numeric_limits<int>::max();
// The adaptive fairness gain never drops below this fraction of DarpOptions::fairness_gain.
constexpr double kMinGainFraction = 1e-3;
}  // namespace

double portable_log(double x) {
  // x = m · 2^k with m in [1/√2, √2): the halvings and doublings are exact.
  int k = 0;
  while (x >= 1.4142135623730951) {
    x *= 0.5;
    ++k;
  }
  while (x < 0.7071067811865476) {
    x *= 2.0;
    --k;
  }
  // log m = 2·atanh(s), s = (m − 1)/(m + 1), |s| ≤ 0.172: the odd series to s^25 is exact to 1e-20.
  // Terms stop once they no longer change the sum (after 2 for the random factors).
  static constexpr double kInverseOdd[] = {1.0,      1.0 / 3,  1.0 / 5,  1.0 / 7,  1.0 / 9,
                                           1.0 / 11, 1.0 / 13, 1.0 / 15, 1.0 / 17, 1.0 / 19,
                                           1.0 / 21, 1.0 / 23, 1.0 / 25};
  const double s = (x - 1.0) / (x + 1.0);
  const double s2 = s * s;
  double term = s;
  double sum = 0;
  for (double inverse : kInverseOdd) {
    const double next = sum + term * inverse;
    if (next == sum) break;
    sum = next;
    term *= s2;
  }
  return 2.0 * sum + k * 0.6931471805599453;
}

DarpWorkspace::DarpWorkspace(const world::HullMask& hull, std::span<const int> start_index,
                             const grid::Grid<double>* weights, std::span<const double> desired,
                             const DarpOptions& options, std::uint64_t seed)
    : n_(static_cast<int>(start_index.size())),
      cell_count_(hull.cell_count()),
      options_(options),
      rng_(seed, world::Stream::kPartition) {
  const auto n = static_cast<std::size_t>(n_);
  const auto cells = static_cast<std::size_t>(cell_count_);
  const auto& mask = hull.mask();

  // The hull graph: cells in (y, x) order, rows, west-neighbour flags and the neighbour table.
  cell_flat_ = hull.cells();
  std::vector<int> hull_index(static_cast<std::size_t>(mask.size()), -1);
  for (std::size_t j = 0; j < cells; ++j) {
    hull_index[static_cast<std::size_t>(cell_flat_[j])] = static_cast<int>(j);
  }
  cell_x_.resize(cells);
  row_start_.resize(cells);
  row_first_.assign(static_cast<std::size_t>(mask.height()) + 1, static_cast<int>(cells));
  neighbours_.assign(4 * cells, -1);
  for (std::size_t j = cells; j-- > 0;) {
    const grid::Cell c = mask.cell(cell_flat_[j]);
    cell_x_[j] = c.x;
    row_start_[j] = c.x == 0 || !mask(c.x - 1, c.y);
    row_first_[static_cast<std::size_t>(c.y)] = static_cast<int>(j);
    for (int d = 0; d < 4; ++d) {
      const grid::Cell nb{c.x + grid::kNeighbourDx[d], c.y + grid::kNeighbourDy[d]};
      if (mask.contains(nb)) {
        neighbours_[4 * j + static_cast<std::size_t>(d)] =
            hull_index[static_cast<std::size_t>(mask.index(nb))];
      }
    }
  }
  for (std::size_t y = row_first_.size() - 1; y-- > 0;) {
    row_first_[y] = std::min(row_first_[y], row_first_[y + 1]);  // rows without hull cells
  }
  // The padded grid for the distance transforms: a ring of blocked cells around the grid, so a
  // neighbour is ±1 or ±width and needs no bounds check.
  padded_width_ = mask.width() + 2;
  pad_of_.resize(cells);
  padded_blank_.assign(static_cast<std::size_t>(padded_width_) * (mask.height() + 2), kBlocked);
  for (std::size_t j = 0; j < cells; ++j) {
    const grid::Cell c = mask.cell(cell_flat_[j]);
    pad_of_[j] = (c.y + 1) * padded_width_ + c.x + 1;
    padded_blank_[static_cast<std::size_t>(pad_of_[j])] = kUnreached;
  }
  start_.resize(n);
  for (std::size_t r = 0; r < n; ++r) {
    start_[r] = hull_index[static_cast<std::size_t>(start_index[r])];
  }
  if (weights != nullptr) {
    weight_.resize(cells);
    for (std::size_t j = 0; j < cells; ++j) weight_[j] = (*weights)[cell_flat_[j]];
  }
  desired_.assign(desired.begin(), desired.end());
  for (double d : desired_) total_weight_ += d;

  // Evaluation matrices: log of the 4-neighbour BFS distance through hull cells from each start.
  queue_.resize(cells);
  pad_queue_.resize(cells);
  pad_near_.resize(padded_blank_.size());
  pad_far_.resize(padded_blank_.size());
  mark_.resize(cells);
  eval_.resize(n * cells);
  std::vector<float> log_of;  // log_of[d] = log d, as far as the distances reach
  for (std::size_t r = 0; r < n; ++r) {
    queue_[0] = start_[r];
    const int reach = hull_bfs(pad_near_, 1);
    while (static_cast<int>(log_of.size()) <= reach) {
      const auto d = static_cast<double>(log_of.size());
      log_of.push_back(d == 0 ? kStartValue : static_cast<float>(portable_log(d)));
    }
    float* e = &eval_[r * cells];
    for (std::size_t j = 0; j < cells; ++j) {
      e[j] = log_of[static_cast<std::size_t>(pad_near_[static_cast<std::size_t>(pad_of_[j])])];
    }
  }

  fair_.assign(n, 0.0);
  gain_.assign(n, options_.fairness_gain);
  last_sign_.assign(n, 0);
  best_value_.resize(cells);
  next_owner_.resize(cells);
  owner_.assign(cells, n_);  // the sentinel "nobody yet", with its own changed_ flag
  region_cells_.assign(n, 0);
  region_weight_.assign(n, 0.0);
  changed_.assign(n + 1, 1);
  run_of_.resize(cells);
  run_x0_.resize(cells);
  run_x1_.resize(cells);
  run_owner_.resize(cells);
  run_parent_.resize(cells);
  run_root_.resize(cells);
  run_weight_.resize(cells);
  row_runs_.resize(row_first_.size());
  components_.assign(n, 0);
  start_root_.assign(n, -1);
  split_.assign(n, 0);
  correction_ = std::make_unique_for_overwrite<float[]>(n * cells);  // untouched until a split

  // The random factors: N log-factors uniform in [1 − rl, 1 + rl], read at a fresh random rotation
  // per UAV and iteration, so each entry gets its own factor at the cost of one addition.
  noise_.resize(cells);
  const double low = 1.0 - options_.rl;
  for (auto& v : noise_) {
    v = static_cast<float>(portable_log(low + 2.0 * options_.rl * rng_.uniform01()));
  }
  noise_offset_.assign(n, 0);
  best_connected_.resize(cells);
  best_balanced_.resize(cells);
}

int DarpWorkspace::hull_bfs(std::vector<int>& dist, int sources) {
  std::copy(padded_blank_.begin(), padded_blank_.end(), dist.begin());
  int* __restrict d = dist.data();
  int* __restrict queue = pad_queue_.data();
  for (int q = 0; q < sources; ++q) {
    const int p = pad_of_[static_cast<std::size_t>(queue_[static_cast<std::size_t>(q)])];
    queue[q] = p;
    d[p] = 0;
  }
  const int offsets[4] = {1, -1, padded_width_, -padded_width_};
  int head = 0;
  int tail = sources;
  int last = 0;
  while (head < tail) {
    const int p = queue[head++];
    last = d[p];
    const int next = last + 1;
    for (int off : offsets) {
      const int k = p + off;
      if (d[k] <= next) continue;  // reached already, or blocked (kBlocked < 0)
      d[k] = next;
      queue[tail++] = k;
    }
    if (!seam_partner_.empty()) {
      const int k = seam_partner_[static_cast<std::size_t>(p)];
      if (k >= 0 && d[k] > next) {
        d[k] = next;
        queue[tail++] = k;
      }
    }
  }
  return last;
}

void DarpWorkspace::add_noise_and_compare(int uav) {
  const auto cells = static_cast<std::size_t>(cell_count_);
  float* __restrict e = &eval_[static_cast<std::size_t>(uav) * cells];
  float* __restrict best = best_value_.data();
  std::int32_t* __restrict next = next_owner_.data();
  const auto fair = static_cast<float>(fair_[static_cast<std::size_t>(uav)]);
  // The random factors of the previous update are applied here, fused with the comparison, so
  // every entry is read and written once per iteration: entry j gets noise_[(j + offset) mod N].
  if (noise_pending_) {
    const auto offset = static_cast<std::size_t>(noise_offset_[static_cast<std::size_t>(uav)]);
    const float* __restrict noise = noise_.data();
    const std::size_t wrap = cells - offset;
    for (std::size_t j = 0; j < wrap; ++j) e[j] += noise[j + offset];
    for (std::size_t j = wrap; j < cells; ++j) e[j] += noise[j - wrap];
  }
  if (uav == 0) {
    for (std::size_t j = 0; j < cells; ++j) {
      best[j] = e[j] + fair;
      next[j] = 0;
    }
    return;
  }
  // Branch-free so that it vectorises; strict "<": ties go to the lowest UAV id.
  for (std::size_t j = 0; j < cells; ++j) {
    const float v = e[j] + fair;
    const float b = best[j];
    const std::int32_t take = -static_cast<std::int32_t>(v < b);
    best[j] = v < b ? v : b;
    next[j] = (next[j] & ~take) | (uav & take);
  }
}

void DarpWorkspace::assign() {
  const auto cells = static_cast<std::size_t>(cell_count_);
  for (int r = 0; r < n_; ++r) add_noise_and_compare(r);
  noise_pending_ = false;
  // Regions that gained or lost cells have stale corrections.
  const std::int32_t* __restrict next = next_owner_.data();
  std::int32_t* __restrict owner = owner_.data();
  for (std::size_t j = 0; j < cells; ++j) {
    if (next[j] != owner[j]) {
      changed_[static_cast<std::size_t>(next[j])] = 1;
      changed_[static_cast<std::size_t>(owner[j])] = 1;
      owner[j] = next[j];
    }
  }
  // The same-owner runs of every row; region sizes follow from the runs.
  int runs = 0;
  for (std::size_t y = 0; y + 1 < row_first_.size(); ++y) {
    row_runs_[y] = runs;
    const auto end = static_cast<std::size_t>(row_first_[y + 1]);
    for (auto j = static_cast<std::size_t>(row_first_[y]); j < end; ++j) {
      if (row_start_[j] || owner[j] != owner[j - 1]) {
        const auto run = static_cast<std::size_t>(runs++);
        run_x0_[run] = cell_x_[j];
        run_owner_[run] = owner[j];
        run_parent_[run] = static_cast<int>(run);
      }
      run_of_[j] = runs - 1;
      run_x1_[static_cast<std::size_t>(runs - 1)] = cell_x_[j];
    }
  }
  row_runs_.back() = runs;
  run_count_ = runs;
  std::fill(region_cells_.begin(), region_cells_.end(), 0);
  for (std::size_t run = 0; run < static_cast<std::size_t>(runs); ++run) {
    region_cells_[static_cast<std::size_t>(run_owner_[run])] += run_x1_[run] - run_x0_[run] + 1;
  }
  if (weight_.empty()) {
    for (std::size_t run = 0; run < static_cast<std::size_t>(runs); ++run) {
      run_weight_[run] = run_x1_[run] - run_x0_[run] + 1;
    }
    for (std::size_t r = 0; r < region_cells_.size(); ++r) region_weight_[r] = region_cells_[r];
  } else {
    std::fill(run_weight_.begin(), run_weight_.begin() + runs, 0.0);
    for (std::size_t j = 0; j < cells; ++j)
      run_weight_[static_cast<std::size_t>(run_of_[j])] += weight_[j];
    std::fill(region_weight_.begin(), region_weight_.end(), 0.0);
    for (std::size_t run = 0; run < static_cast<std::size_t>(runs); ++run) {
      region_weight_[static_cast<std::size_t>(run_owner_[run])] += run_weight_[run];
    }
  }
}

int DarpWorkspace::find_root(int run) {
  int* parent = run_parent_.data();
  int root = run;
  while (parent[root] != root) root = parent[root];
  while (parent[run] != root) {
    const int up = parent[run];
    parent[run] = root;
    run = up;
  }
  return root;
}

void DarpWorkspace::check_connectivity() {
  // Join each run with the same-owner runs of the row below whose x ranges overlap (4-adjacency).
  for (std::size_t y = 1; y + 1 < row_runs_.size(); ++y) {
    int a = row_runs_[y - 1];
    const int a_end = row_runs_[y];
    int b = row_runs_[y];
    const int b_end = row_runs_[y + 1];
    while (a < a_end && b < b_end) {
      const auto ua = static_cast<std::size_t>(a);
      const auto ub = static_cast<std::size_t>(b);
      if (run_owner_[ua] == run_owner_[ub] && run_x0_[ua] <= run_x1_[ub] &&
          run_x0_[ub] <= run_x1_[ua]) {
        const int ra = find_root(a);
        const int rb = find_root(b);
        // The lower index becomes the root, so roots do not depend on the order of the joins.
        if (ra != rb) run_parent_[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
      }
      if (run_x1_[ua] < run_x1_[ub]) {
        ++a;
      } else {
        ++b;
      }
    }
  }
  join_across_seam();
  std::fill(components_.begin(), components_.end(), 0);
  for (int run = 0; run < run_count_; ++run) {
    const int root = find_root(run);
    run_root_[static_cast<std::size_t>(run)] = root;
    if (root == run)
      ++components_[static_cast<std::size_t>(run_owner_[static_cast<std::size_t>(run)])];
  }
  split_count_ = 0;
  for (std::size_t r = 0; r < static_cast<std::size_t>(n_); ++r) {
    split_[r] = components_[r] > 1 ? 1 : 0;
    split_count_ += split_[r];
    start_root_[r] =
        run_root_[static_cast<std::size_t>(run_of_[static_cast<std::size_t>(start_[r])])];
  }
  // Weight outside the start components (what a repair would have to hand over).
  stray_weight_ = 0;
  if (split_count_ == 0) return;
  for (std::size_t run = 0; run < static_cast<std::size_t>(run_count_); ++run) {
    if (run_root_[run] != start_root_[static_cast<std::size_t>(run_owner_[run])]) {
      stray_weight_ += run_weight_[run];
    }
  }
}

double DarpWorkspace::discrepancy() const {
  double worst = 0;
  for (std::size_t r = 0; r < desired_.size(); ++r) {
    worst = std::max(worst, std::abs(region_weight_[r] - desired_[r]));
  }
  return worst;
}

void DarpWorkspace::build_correction(int uav) {
  const auto cells = static_cast<std::size_t>(cell_count_);
  const auto r = static_cast<std::size_t>(uav);
  // Distance to the start's component …
  int sources = 0;
  for (std::size_t j = 0; j < cells; ++j) {
    if (owner_[j] == uav && run_root_[static_cast<std::size_t>(run_of_[j])] == start_root_[r]) {
      queue_[static_cast<std::size_t>(sources++)] = static_cast<int>(j);
    }
  }
  const double near_max = hull_bfs(pad_near_, sources);
  // … and to the region's other components.
  sources = 0;
  for (std::size_t j = 0; j < cells; ++j) {
    if (owner_[j] == uav && run_root_[static_cast<std::size_t>(run_of_[j])] != start_root_[r]) {
      queue_[static_cast<std::size_t>(sources++)] = static_cast<int>(j);
    }
  }
  const double far_max = hull_bfs(pad_far_, sources);
  // Both normalised to [0, 1] as in the reference; their difference is low near the start's
  // component and far from the stray parts (there the UAV should keep cells) and high near the
  // stray parts (there it should give them up).
  const double near_scale = near_max > 0 ? 1.0 / near_max : 0.0;
  const double far_scale = far_max > 0 ? 1.0 / far_max : 0.0;
  float* c = correction_.get() + r * cells;
  float lo = std::numeric_limits<float>::max();
  float hi = std::numeric_limits<float>::lowest();
  for (std::size_t j = 0; j < cells; ++j) {
    const auto p = static_cast<std::size_t>(pad_of_[j]);
    const auto diff = static_cast<float>(pad_near_[p] * near_scale - pad_far_[p] * far_scale);
    c[j] = diff;
    lo = std::min(lo, diff);
    hi = std::max(hi, diff);
  }
  // Rescaled into [1 − cc, 1 + cc], geometrically (linearly in the log domain).
  const auto log_lo = static_cast<float>(portable_log(1.0 - options_.cc));
  const auto log_hi = static_cast<float>(portable_log(1.0 + options_.cc));
  const float scale = hi > lo ? (log_hi - log_lo) / (hi - lo) : 0.0f;
  for (std::size_t j = 0; j < cells; ++j) c[j] = log_lo + (c[j] - lo) * scale;
}

void DarpWorkspace::update_fairness(double tolerance_weight) {
  const auto n = static_cast<std::size_t>(n_);
  // UAV r is over its share when w_r − d_r > tol · d_r / D, the reference's band: with it, a UAV
  // under by more than tol · (D − d_r) / D implies one over. When no UAV is over, every multiplier
  // is 1 (balance is then within the tolerance and only connectivity is left to fix).
  bool any_over = false;
  for (std::size_t r = 0; r < n; ++r) {
    const double allowed = tolerance_weight * desired_[r] / total_weight_ + 1e-9 * total_weight_;
    if (region_weight_[r] - desired_[r] > allowed) any_over = true;
  }
  if (!any_over) return;
  // Otherwise UAV r's multiplier is exp(g_r · (w_r − d_r) / d_r). The gain g_r adapts per UAV: it
  // shrinks when the share error changes sign (the last step overshot, typically a column of
  // equidistant cells flipping as a block) and grows back while the sign holds.
  const double max_gain = options_.fairness_gain;
  const double min_gain = max_gain * kMinGainFraction;
  double highest = std::numeric_limits<double>::lowest();
  for (std::size_t r = 0; r < n; ++r) {
    const double error = (region_weight_[r] - desired_[r]) / desired_[r];
    const int sign = (error > 0) - (error < 0);
    if (sign != 0 && last_sign_[r] != 0) {
      gain_[r] = sign == last_sign_[r] ? std::min(max_gain, gain_[r] * options_.gain_growth)
                                       : std::max(min_gain, gain_[r] * options_.gain_shrink);
    }
    if (sign != 0) last_sign_[r] = sign;
    fair_[r] += std::clamp(gain_[r] * error, -kMaxFairStep, kMaxFairStep);
    highest = std::max(highest, fair_[r]);
  }
  // A factor common to all UAVs changes no argmin: keep the largest multiplier at 1. A UAV that can
  // never reach its share (its start walled in) stops at the floor instead of drifting away.
  for (auto& f : fair_) f = std::max(f - highest, -kMaxFairSpread);
}

void DarpWorkspace::update(double tolerance_weight) {
  const auto cells = static_cast<std::size_t>(cell_count_);
  const auto n = static_cast<std::size_t>(n_);
  update_fairness(tolerance_weight);
  // Connectivity corrections of split regions (rebuilt only when the region changed).
  for (std::size_t r = 0; r < n; ++r) {
    if (!split_[r]) continue;
    if (changed_[r]) {
      build_correction(static_cast<int>(r));
      changed_[r] = 0;
    }
    float* __restrict e = &eval_[r * cells];
    const float* __restrict c = correction_.get() + r * cells;
    for (std::size_t j = 0; j < cells; ++j) e[j] += c[j];
  }
  // Random factors: drawn now, applied at the next assignment (fused with it).
  for (std::size_t r = 0; r < n; ++r) noise_offset_[r] = static_cast<int>(rng_.below(cells));
  noise_pending_ = true;
}

void DarpWorkspace::remember_connected(double discrepancy) {
  if (has_connected() && discrepancy >= best_connected_discrepancy_) return;
  best_connected_ = owner_;  // equal sizes: copies without allocating
  best_connected_discrepancy_ = discrepancy;
}

void DarpWorkspace::remember_balanced(double score) {
  if (best_balanced_score_ >= 0 && score >= best_balanced_score_) return;
  best_balanced_ = owner_;
  best_balanced_score_ = score;
}

double DarpWorkspace::repair_best_balanced() {
  if (best_balanced_score_ < 0) return -1;
  std::vector<std::int32_t>& owner = best_balanced_;
  // Mark the start components (BFS inside each region from its start) and queue them.
  std::vector<int>& mark = mark_;
  std::fill(mark.begin(), mark.end(), 0);
  std::size_t tail = 0;
  for (std::size_t r = 0; r < start_.size(); ++r) {
    std::size_t head = tail;
    queue_[tail++] = start_[r];
    mark[static_cast<std::size_t>(start_[r])] = 1;
    while (head < tail) {
      const auto j = static_cast<std::size_t>(queue_[head++]);
      for (int d = 0; d < 4; ++d) {
        const int k = neighbours_[4 * j + static_cast<std::size_t>(d)];
        if (k < 0 || mark[static_cast<std::size_t>(k)] ||
            owner[static_cast<std::size_t>(k)] != static_cast<std::int32_t>(r)) {
          continue;
        }
        mark[static_cast<std::size_t>(k)] = 1;
        queue_[tail++] = k;
      }
    }
  }
  // Every other cell takes the owner of the start component it is reached from first, so it joins
  // that region through a path of cells that all join it too.
  std::size_t head = 0;
  while (head < tail) {
    const auto j = static_cast<std::size_t>(queue_[head++]);
    for (int d = 0; d < 4; ++d) {
      const int k = neighbours_[4 * j + static_cast<std::size_t>(d)];
      if (k < 0 || mark[static_cast<std::size_t>(k)]) continue;
      mark[static_cast<std::size_t>(k)] = 1;
      owner[static_cast<std::size_t>(k)] = owner[j];
      queue_[tail++] = k;
    }
  }
  std::vector<int> region_cells;
  std::vector<double> region_weight;
  totals_of(owner, region_cells, region_weight);
  double worst = 0;
  for (std::size_t r = 0; r < desired_.size(); ++r) {
    worst = std::max(worst, std::abs(region_weight[r] - desired_[r]));
  }
  if (!has_connected() || worst < best_connected_discrepancy_) {
    best_connected_ = owner;
    best_connected_discrepancy_ = worst;
  }
  return worst;
}

void DarpWorkspace::totals_of(const std::vector<std::int32_t>& owner, std::vector<int>& cells,
                              std::vector<double>& weight) const {
  cells.assign(static_cast<std::size_t>(n_), 0);
  weight.assign(static_cast<std::size_t>(n_), 0.0);
  for (std::size_t j = 0; j < owner.size(); ++j) {
    const auto o = static_cast<std::size_t>(owner[j]);
    ++cells[o];
    weight[o] += weight_.empty() ? 1.0 : weight_[j];
  }
}

void DarpWorkspace::export_assignment(Which which, grid::Grid<std::int16_t>& owner,
                                      std::vector<int>& region_cells,
                                      std::vector<double>& region_weight) const {
  const auto& from = which == Which::kBestConnected ? best_connected_ : owner_;
  for (std::size_t j = 0; j < from.size(); ++j) {
    owner[cell_flat_[j]] = static_cast<std::int16_t>(from[j]);
  }
  totals_of(from, region_cells, region_weight);
}

void DarpWorkspace::use_allowed_distances(const grid::Grid<std::uint8_t>& allowed,
                                          std::span<const int> start_index,
                                          const grid::EdgeSteps& flights) {
  grid::DistanceService distances(allowed, flights, /*cached_fields=*/1);
  const auto cells = static_cast<std::size_t>(cell_count_);
  for (std::size_t r = 0; r < start_index.size(); ++r) {
    const grid::Grid<int>& field = distances.field(allowed.cell(start_index[r]));
    int far = 0;
    for (std::size_t j = 0; j < cells; ++j) {
      const int d = field[cell_flat_[j]];
      if (d < grid::kUnreachable) far = std::max(far, d);
    }
    float* e = &eval_[r * cells];
    for (std::size_t j = 0; j < cells; ++j) {
      const int d = std::min(field[cell_flat_[j]], far + 1);
      e[j] = d == 0 ? kStartValue : static_cast<float>(portable_log(static_cast<double>(d)));
    }
  }
}

}  // namespace hullinspect::partition::detail
