#include "hullinspect/planners/band_partition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <numeric>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/grid/distance.hpp"
#include "hullinspect/world/standoff_surface.hpp"

namespace hullinspect::planners {

std::vector<int> column_band_starts(std::span<const int> width_of_column) {
  std::vector<int> start(width_of_column.size(), 0);
  int run_start = 0;
  for (std::size_t x = 0; x < width_of_column.size(); ++x) {
    const int w = std::max(1, width_of_column[x]);
    if (x == 0 || width_of_column[x] != width_of_column[x - 1]) run_start = static_cast<int>(x);
    start[x] = run_start + (static_cast<int>(x) - run_start) / w * w;
  }
  return start;
}

namespace {
/// The boustrophedon's order of cells: bands numbered left to right, odd ones flown down; within
/// a row of a band, left to right.
class BandOrder {
 public:
  BandOrder(std::span<const int> band_start, int width) : width_(width) {
    band_of_.assign(static_cast<std::size_t>(width), 0);
    for (int x = 1; x < width; ++x) {
      band_of_[static_cast<std::size_t>(x)] =
          band_of_[static_cast<std::size_t>(x - 1)] +
          (band_start[static_cast<std::size_t>(x)] != band_start[static_cast<std::size_t>(x - 1)]);
    }
  }
  /// (band, row in the band's direction, x): increasing along the boustrophedon.
  std::array<int, 3> key(int i) const {
    const int x = i % width_;
    const int y = i / width_;
    const int band = band_of_[static_cast<std::size_t>(x)];
    return {band, band % 2 == 0 ? y : -y, x};
  }
  /// Every hull cell in the boustrophedon's order (`sort` of all of them), read band by band.
  std::vector<int> hull_cells(const world::HullMask& hull) const {
    std::vector<int> ordered;
    ordered.reserve(hull.cells().size());
    int first = 0;  // the band's first column
    while (first < width_) {
      int end = first + 1;
      while (end < width_ &&
             band_of_[static_cast<std::size_t>(end)] == band_of_[static_cast<std::size_t>(first)])
        ++end;
      const bool up = band_of_[static_cast<std::size_t>(first)] % 2 == 0;
      for (int r = 0; r < hull.height(); ++r) {
        const int y = up ? r : hull.height() - 1 - r;
        for (int x = first; x < end; ++x) {
          if (hull.is_hull(x, y)) ordered.push_back(hull.mask().index(x, y));
        }
      }
      first = end;
    }
    return ordered;
  }
  /// Sorts cells into the boustrophedon's order.
  void sort(std::span<int> cells) const {
    std::sort(cells.begin(), cells.end(), [this](int a, int b) { return key(a) < key(b); });
  }
  /// Whether `ordered[j]` (cells in this order) is the first of its band / of its row of a band.
  bool begins_band(std::span<const int> ordered, std::size_t j) const {
    return j == 0 || key(ordered[j - 1])[0] != key(ordered[j])[0];
  }
  bool begins_row(std::span<const int> ordered, std::size_t j) const {
    return begins_band(ordered, j) || key(ordered[j - 1])[1] != key(ordered[j])[1];
  }
  /// The flight `ordered[j]` begins: `row_cost` for a row of a band, `band_cost` more for a band.
  double begun(std::span<const int> ordered, std::size_t j, double row_cost,
               double band_cost) const {
    return (begins_row(ordered, j) ? row_cost : 0.0) + (begins_band(ordered, j) ? band_cost : 0.0);
  }

 private:
  int width_;
  std::vector<int> band_of_;
};
}  // namespace

BandPieces::BandPieces(const world::HullMask& hull, const grid::Grid<double>& extra,
                       std::span<const int> band_start, std::span<const grid::Cell> starts,
                       double row_cost, double band_cost)
    : hull_(&hull) {
  const int n = static_cast<int>(starts.size());
  const bool weighted = extra.size() > 0;
  const BandOrder band_order(band_start, hull.width());
  order_ = band_order.hull_cells(hull);
  // The rows of the bands, in order: [row_begin_[r], row_begin_[r + 1]) of `order_`, their work
  // and the prefix sums of their extra work.
  extra_before_.push_back(0.0);
  for (std::size_t j = 0; j < order_.size(); ++j) {
    if (band_order.begins_row(order_, j)) {
      row_begin_.push_back(j);
      row_work_.push_back(0.0);
      extra_before_.push_back(extra_before_.back());
    }
    const double more = weighted ? extra[order_[j]] : 0.0;
    const double work = band_order.begun(order_, j, row_cost, band_cost) + more;
    row_work_.back() += work;
    extra_before_.back() += more;
    total_ += work;
  }
  row_begin_.push_back(order_.size());
  // The pieces go to the UAVs in the order of their starts along the hull.
  uav_of_piece_.resize(static_cast<std::size_t>(n));
  std::iota(uav_of_piece_.begin(), uav_of_piece_.end(), 0);
  std::stable_sort(uav_of_piece_.begin(), uav_of_piece_.end(), [&](int a, int b) {
    const grid::Cell sa = starts[static_cast<std::size_t>(a)];
    const grid::Cell sb = starts[static_cast<std::size_t>(b)];
    return sa.x != sb.x ? sa.x < sb.x : sa.y < sb.y;
  });
  if (rows() < static_cast<std::size_t>(n)) {
    throw Error(fmt::format("band partition: {} rows of bands for {} UAVs", rows(), n));
  }
}

double BandPieces::common_share(std::span<const double> offset) const {
  double common = total_;
  for (int k = 0; k < uavs(); ++k) common += offset_of(offset, k);
  return common / uavs();
}

std::vector<std::size_t> BandPieces::balanced_cuts(std::span<const double> offset) const {
  // Each UAV's share of the total is less its offset (work it has besides its piece's), so that
  // piece plus offset comes to the same common share for every UAV.
  const int n = uavs();
  const double common = common_share(offset);
  // Cut where the running sum is nearest each share, between rows (a row's cells are seen by the
  // same footprints); every piece gets at least one row.
  std::vector<std::size_t> cuts;
  std::size_t next = 0;
  double running = 0;
  double target = 0;
  for (int piece = 0; piece < n; ++piece) {
    target += common - offset_of(offset, uav_of_piece(piece));
    const std::size_t later = static_cast<std::size_t>(n - piece - 1);
    const std::size_t first = next;
    while (next + later < rows()) {
      if (piece < n - 1 && next > first &&
          std::abs(running + row_work_[next] - target) > std::abs(running - target)) {
        break;
      }
      running += row_work_[next];
      ++next;
    }
    if (piece < n - 1) cuts.push_back(next);
  }
  return cuts;
}

void BandPieces::assign_rows(grid::Grid<std::int16_t>& owner, std::size_t lo, std::size_t hi,
                             int k) const {
  for (std::size_t j = row_begin_[lo]; j < row_begin_[hi]; ++j)
    owner[order_[j]] = static_cast<std::int16_t>(k);
}

std::pair<int, int> BandPieces::columns(std::size_t lo, std::size_t hi) const {
  const int width = hull_->width();
  int first = width;
  int last = -1;
  for (std::size_t j = row_begin_[lo]; j < row_begin_[hi]; ++j) {
    first = std::min(first, order_[j] % width);
    last = std::max(last, order_[j] % width);
  }
  return {first, last};
}

double BandPieces::work(std::size_t lo, std::size_t hi) const {
  double sum = 0;
  for (std::size_t r = lo; r < hi; ++r) sum += row_work_[r];
  return sum;
}

partition::Partition BandPieces::cut(std::span<const std::size_t> cuts,
                                     std::span<const double> offset) const {
  const auto t0 = std::chrono::steady_clock::now();
  const int n = uavs();
  const int width = hull_->width();
  partition::Partition out;
  out.owner = grid::Grid<std::int16_t>(width, hull_->height(), -1);
  out.region_cells.assign(static_cast<std::size_t>(n), 0);
  out.region_weight.assign(static_cast<std::size_t>(n), 0.0);
  out.desired_weight.assign(static_cast<std::size_t>(n), 0.0);
  const double common = common_share(offset);
  for (int piece = 0; piece < n; ++piece) {
    const std::size_t lo = piece == 0 ? 0 : cuts[static_cast<std::size_t>(piece - 1)];
    const std::size_t hi = piece == n - 1 ? rows() : cuts[static_cast<std::size_t>(piece)];
    const int k = uav_of_piece(piece);
    const auto kk = static_cast<std::size_t>(k);
    assign_rows(out.owner, lo, hi, k);
    out.region_cells[kk] = static_cast<int>(row_begin_[hi] - row_begin_[lo]);
    out.region_weight[kk] = work(lo, hi);
    out.desired_weight[kk] = common - offset_of(offset, k);
  }
  grid::Grid<std::uint8_t> in_region(width, hull_->height(), 0);
  grid::Grid<int> labels;
  grid::BfsScratch scratch;
  const grid::EdgeSteps seam = world::seam_links(*hull_);  // a piece may cross the seam
  for (int k = 0; k < n; ++k) {
    for (int i : hull_->cells()) in_region[i] = out.owner[i] == k;
    if (grid::label_components(in_region, labels, scratch, seam) != 1) {
      throw Error(fmt::format("band partition: the piece of UAV {} is not 4-connected on hull '{}'",
                              k, hull_->source()));
    }
  }
  double worst = 0;
  for (int k = 0; k < n; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    worst = std::max(worst, std::abs(out.region_weight[kk] - out.desired_weight[kk]));
  }
  out.tolerance = worst;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

partition::Partition band_order_partition(const world::HullMask& hull,
                                          const grid::Grid<double>& extra,
                                          std::span<const int> band_start,
                                          std::span<const grid::Cell> starts, double row_cost,
                                          double band_cost, std::span<const double> offset) {
  const BandPieces pieces(hull, extra, band_start, starts, row_cost, band_cost);
  return pieces.cut(pieces.balanced_cuts(offset), offset);
}

double earliest_common_end(const std::function<bool(double)>& fits) {
  double lo = 0.0;
  double hi = 1.0;
  while (!fits(hi)) hi *= 2.0;
  for (int round = 0; round < 60 && hi - lo > 0.25; ++round) {
    const double mid = 0.5 * (lo + hi);
    (fits(mid) ? hi : lo) = mid;
  }
  return hi;
}

void split_in_band_order(std::vector<int>& cells, int width, std::span<const int> band_start,
                         std::span<const std::pair<int, grid::Cell>> uavs,
                         std::span<const double> load, double row_cost, double band_cost,
                         const std::function<void(int, int)>& assign) {
  if (cells.empty() || uavs.empty()) return;
  const BandOrder band_order(band_start, width);
  band_order.sort(cells);
  const auto cell_at = [width](int i) { return grid::Cell{i % width, i / width}; };
  // The work each cell adds: a row or band begun there, and within a run the flight across a
  // gap from the cell before it (rows and bands swept already) beyond what a band begun pays.
  // Counted free, a run could take cells on both sides of a long swept stretch, and its UAV
  // would fly back and forth between them.
  int widest_band = 1;
  for (std::size_t x = 0; x < band_start.size(); ++x)
    widest_band = std::max(widest_band, static_cast<int>(x) - band_start[x] + 1);
  const int free_gap = widest_band + 1;
  std::vector<double> work(cells.size());
  std::vector<double> gap(cells.size(), 0.0);
  for (std::size_t j = 0; j < cells.size(); ++j) {
    work[j] = band_order.begun(cells, j, row_cost, band_cost);
    if (j > 0) {
      const int d = grid::manhattan(cell_at(cells[j - 1]), cell_at(cells[j]));
      gap[j] = std::max(0, d - free_gap);
    }
  }
  const auto split = [&](double t, bool give) {
    std::size_t c = 0;
    for (const auto& [k, pos] : uavs) {
      const std::size_t first = c;
      const int to_first = c < cells.size() ? grid::manhattan(pos, cell_at(cells[first])) : 0;
      double run = 0.0;
      while (c < cells.size()) {
        // A run begun mid-row still pays for its first row.
        const double step = c == first ? std::max(work[c], row_cost) : work[c] + gap[c];
        const int flight = std::min(to_first, grid::manhattan(pos, cell_at(cells[c])));
        if (load[static_cast<std::size_t>(k)] + flight + run + step > t) break;
        run += step;
        if (give) assign(k, cells[c]);
        ++c;
      }
    }
    return c == cells.size();
  };
  split(earliest_common_end([&](double t) { return split(t, false); }), true);
}

}  // namespace hullinspect::planners
