// Column slabs that end together (slab_split.hpp).

#include "hullinspect/planners/slab_split.hpp"

#include <algorithm>

#include "hullinspect/planners/band_partition.hpp"

namespace hullinspect::planners {

void split_in_slabs(std::span<const int> cells, int width,
                    std::span<const std::pair<int, grid::Cell>> uavs, std::span<const double> load,
                    double per_column, const std::function<void(int, int)>& assign) {
  if (cells.empty() || uavs.empty()) return;
  const auto split = [&](double t, bool give) {
    std::size_t c = 0;
    for (const auto& [k, pos] : uavs) {
      const std::size_t first = c;
      while (c < cells.size()) {
        const int x_lo = cells[first] % width;
        const int x_hi = cells[c] % width;
        const int flight = pos.x < x_lo   ? x_lo - pos.x
                           : pos.x > x_hi ? pos.x - x_hi
                                          : std::min(pos.x - x_lo, x_hi - pos.x);
        const double cost = load[static_cast<std::size_t>(k)] + per_column * flight +
                            static_cast<double>(c - first + 1);
        if (cost > t) break;
        if (give) assign(k, cells[c]);
        ++c;
      }
    }
    return c == cells.size();
  };
  split(earliest_common_end([&](double t) { return split(t, false); }), true);
}

}  // namespace hullinspect::planners
