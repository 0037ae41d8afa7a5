#include "hullinspect/planners/part_tsp_local_map.hpp"

#include <algorithm>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/no_fly.hpp"

namespace hullinspect::planners::part_tsp {

namespace {
constexpr int kCellsSlot = 0;
int value_slot(std::int8_t value) {
  return value == sim::kUnknown ? 1 : 2;
}
}  // namespace

LocalMaps::LocalMaps(const grid::Grid<std::int16_t>& owner, const grid::Grid<std::int8_t>& prior,
                     bool use_prior, int uavs, int s1, int s2)
    : owner_(owner),
      values_(owner.width(), owner.height(), sim::kNotHull),
      seen_from_z2_(owner.width(), owner.height(), 0),
      layouts_{StripLayout{s1, owner.height()}, StripLayout{s2, owner.height()}},
      regions_(static_cast<std::size_t>(uavs)) {
  if (prior.width() != owner.width() || prior.height() != owner.height()) {
    throw LogicError("LocalMaps: the prior and the partition differ in size");
  }
  std::vector<int> x_min(regions_.size(), owner.width());
  std::vector<int> x_max(regions_.size(), -1);
  for (int i = 0; i < owner.size(); ++i) {
    const int k = owner[i];
    if (k < 0) continue;
    if (k >= uavs) throw LogicError("LocalMaps: the partition names a UAV beyond the fleet");
    const auto uk = static_cast<std::size_t>(k);
    const int x = owner.cell(i).x;
    x_min[uk] = std::min(x_min[uk], x);
    x_max[uk] = std::max(x_max[uk], x);
  }
  for (std::size_t k = 0; k < regions_.size(); ++k) {
    Region& r = regions_[k];
    r.x_begin = x_max[k] < 0 ? 0 : x_min[k];
    r.width = x_max[k] < 0 ? 0 : x_max[k] - x_min[k] + 1;
    for (int z = 1; z <= 2; ++z) {
      r.columns[static_cast<std::size_t>(z - 1)].assign(
          static_cast<std::size_t>(layout(z).strips() * r.width * 3), 0);
    }
  }
  for (int i = 0; i < owner.size(); ++i) {
    const int k = owner[i];
    if (k < 0) continue;
    Region& r = regions_[static_cast<std::size_t>(k)];
    const grid::Cell c = owner.cell(i);
    const std::int8_t v = use_prior && prior[i] == 1 ? sim::kCorrosionSeen : sim::kUnknown;
    values_[i] = v;
    ++r.cells;
    ++(v == sim::kUnknown ? r.zeros : r.twos);
    for (int z = 1; z <= 2; ++z) {
      auto& cols = r.columns[static_cast<std::size_t>(z - 1)];
      const std::size_t slot = column_slot(r, z, c.x, c.y);
      ++cols[slot + kCellsSlot];
      ++cols[slot + static_cast<std::size_t>(value_slot(v))];
    }
  }
  start_values_ = values_;
}

std::size_t LocalMaps::column_slot(const Region& r, int z, int x, int y) const {
  const int strip = layout(z).strip_of(y);
  return static_cast<std::size_t>((strip * r.width + (x - r.x_begin)) * 3);
}

int LocalMaps::column_count(int k, int z, std::int8_t value, int strip, int x) const {
  const Region& r = region(k);
  if (x < r.x_begin || x >= r.x_begin + r.width) return 0;
  const auto& cols = r.columns[static_cast<std::size_t>(z - 1)];
  return cols[static_cast<std::size_t>((strip * r.width + (x - r.x_begin)) * 3 +
                                       value_slot(value))];
}

int LocalMaps::column_cells(int k, int z, int strip, int x) const {
  const Region& r = region(k);
  if (x < r.x_begin || x >= r.x_begin + r.width) return 0;
  const auto& cols = r.columns[static_cast<std::size_t>(z - 1)];
  return cols[static_cast<std::size_t>((strip * r.width + (x - r.x_begin)) * 3 + kCellsSlot)];
}

void LocalMaps::set_value(int index, std::int8_t value) {
  const std::int8_t old = values_[index];
  if (old == value) return;
  Region& r = regions_[static_cast<std::size_t>(owner_[index])];
  const grid::Cell c = owner_.cell(index);
  const bool old_counted = old == sim::kUnknown || old == sim::kCorrosionSeen;
  const bool new_counted = value == sim::kUnknown || value == sim::kCorrosionSeen;
  if (old == sim::kUnknown) --r.zeros;
  if (old == sim::kCorrosionSeen) --r.twos;
  if (value == sim::kUnknown) ++r.zeros;
  if (value == sim::kCorrosionSeen) ++r.twos;
  for (int z = 1; z <= 2; ++z) {
    auto& cols = r.columns[static_cast<std::size_t>(z - 1)];
    const std::size_t slot = column_slot(r, z, c.x, c.y);
    if (old_counted) --cols[slot + static_cast<std::size_t>(value_slot(old))];
    if (new_counted) ++cols[slot + static_cast<std::size_t>(value_slot(value))];
  }
  values_[index] = value;
}

void LocalMaps::count(Region& r, int index, std::int8_t value, int delta) {
  const grid::Cell c = owner_.cell(index);
  r.cells += delta;
  if (value == sim::kUnknown) r.zeros += delta;
  if (value == sim::kCorrosionSeen) r.twos += delta;
  const bool counted = value == sim::kUnknown || value == sim::kCorrosionSeen;
  for (int z = 1; z <= 2; ++z) {
    auto& cols = r.columns[static_cast<std::size_t>(z - 1)];
    const std::size_t slot = column_slot(r, z, c.x, c.y);
    cols[slot + kCellsSlot] += delta;
    if (counted) cols[slot + static_cast<std::size_t>(value_slot(value))] += delta;
  }
}

void LocalMaps::widen(Region& r, int x_begin, int x_end) {
  if (r.width > 0) {
    x_begin = std::min(x_begin, r.x_begin);
    x_end = std::max(x_end, r.x_begin + r.width);
  }
  if (r.width > 0 && x_begin == r.x_begin && x_end == r.x_begin + r.width) return;
  const int width = x_end - x_begin;
  for (int z = 1; z <= 2; ++z) {
    auto& cols = r.columns[static_cast<std::size_t>(z - 1)];
    std::vector<int> wider(static_cast<std::size_t>(layout(z).strips() * width * 3), 0);
    for (int j = 0; j < layout(z).strips() && r.width > 0; ++j) {
      for (int x = r.x_begin; x < r.x_begin + r.width; ++x) {
        for (int v = 0; v < 3; ++v) {
          wider[static_cast<std::size_t>((j * width + x - x_begin) * 3 + v)] =
              cols[static_cast<std::size_t>((j * r.width + x - r.x_begin) * 3 + v)];
        }
      }
    }
    cols = std::move(wider);
  }
  r.x_begin = x_begin;
  r.width = width;
}

void LocalMaps::hand_over(std::span<const int> cells, int to, bool forget) {
  if (cells.empty()) return;
  if (to < 0 || to >= uavs()) throw LogicError("LocalMaps: a hand-over to a UAV beyond the fleet");
  Region& target = regions_[static_cast<std::size_t>(to)];
  int x_min = width();
  int x_max = -1;
  for (int i : cells) {
    if (owner_[i] < 0) throw LogicError("LocalMaps: a hand-over of a cell off the hull");
    x_min = std::min(x_min, owner_.cell(i).x);
    x_max = std::max(x_max, owner_.cell(i).x);
  }
  widen(target, x_min, x_max + 1);
  for (int i : cells) {
    const int from = owner_[i];
    if (from == to && !forget) continue;
    count(regions_[static_cast<std::size_t>(from)], i, values_[i], -1);
    owner_[i] = static_cast<std::int16_t>(to);
    if (forget) {
      values_[i] = start_values_[i];
      seen_from_z2_[i] = 0;
    }
    count(target, i, values_[i], +1);
  }
}

void LocalMaps::write_off(const grid::Grid<std::uint8_t>& reach) {
  reach_ = &reach;
  for (int i = 0; i < owner_.size(); ++i) {
    if (owner_[i] < 0) continue;
    const bool can_see = (reach[i] & world::kReachZ2) != 0;
    const bool can_inspect = (reach[i] & world::kReachZ1) != 0;
    if (!can_see) {
      set_value(i, sim::kClean);
    } else if (values_[i] == sim::kCorrosionSeen && !can_inspect) {
      // Only the prior says 2 here: if the cell is clean it still has to be seen (from z = 2) to
      // be known, so it becomes a coverage target; if it is corroded, that look finds it and
      // ingest() writes it off.
      set_value(i, sim::kUnknown);
    }
  }
  start_values_ = values_;
}

LocalEvents LocalMaps::ingest(int k, std::span<const sim::Reading> readings) {
  LocalEvents events;
  for (const sim::Reading& reading : readings) {
    const int i = reading.index;
    if (owner_[i] != k) continue;  // M^k holds R_k only
    const std::int8_t before = values_[i];
    switch (reading.value) {
      case sim::kClean:
        set_value(i, sim::kClean);
        break;
      case sim::kCorrosionSeen:  // corroded, seen from z = 2
        if (seen_from_z2_[i] == 0) {
          seen_from_z2_[i] = 1;
          events.detection = true;
        }
        if (before != sim::kInspected) {
          const bool can_inspect = reach_ == nullptr || ((*reach_)[i] & world::kReachZ1) != 0;
          set_value(i, can_inspect ? sim::kCorrosionSeen : sim::kClean);
        }
        break;
      case sim::kInspected:  // corroded, seen from z = 1
        if (before != sim::kInspected) {
          set_value(i, sim::kInspected);
          events.inspection = true;
        }
        break;
      default:
        throw LogicError("LocalMaps: a reading with a value other than 1, 2 or 3");
    }
  }
  return events;
}

}  // namespace hullinspect::planners::part_tsp
