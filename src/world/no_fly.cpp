#include "hullinspect/world/no_fly.hpp"

#include "hullinspect/world/cell_map.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "hullinspect/world/standoff_surface.hpp"

namespace hullinspect::world {

NoFlyMask make_no_fly_mask(const HullMask& hull, const std::filesystem::path& file,
                           std::span<const CellBox> boxes) {
  NoFlyMask mask(hull.width(), hull.height(), 0);
  if (!file.empty()) {
    const grid::Grid<std::uint8_t> read = load_cell_map(file);
    if (read.width() != hull.width() || read.height() != hull.height()) {
      throw InputError(file.string(), 0,
                       fmt::format("the no-fly mask is {} × {} but the hull is {} × {}",
                                   read.width(), read.height(), hull.width(), hull.height()));
    }
    for (int i = 0; i < read.size(); ++i) mask[i] = read[i] != 0 ? 1 : 0;
  }
  for (const CellBox& b : boxes) {
    if (b.x0 < 0 || b.y0 < 0 || b.x1 >= hull.width() || b.y1 >= hull.height() || b.x0 > b.x1 ||
        b.y0 > b.y1) {
      throw ParameterError("no-fly-box",
                           fmt::format("box {},{},{},{} must satisfy 0 <= X0 <= X1 < {} and "
                                       "0 <= Y0 <= Y1 < {}",
                                       b.x0, b.y0, b.x1, b.y1, hull.width(), hull.height()));
    }
    for (int y = b.y0; y <= b.y1; ++y) {
      for (int x = b.x0; x <= b.x1; ++x) mask(x, y) = 1;
    }
  }
  return mask;
}

CellBox parse_cell_box(const std::string& text, const std::string& option) {
  int v[4];
  std::size_t pos = 0;
  for (int k = 0; k < 4; ++k) {
    const std::size_t end = k < 3 ? text.find(',', pos) : text.size();
    const std::string part =
        text.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    bool ok = end != std::string::npos && !part.empty() && part.size() <= 6;
    int value = 0;
    for (std::size_t i = 0; ok && i < part.size(); ++i) {
      const bool digit = part[i] >= '0' && part[i] <= '9';
      if (!digit) ok = false;
      value = value * 10 + (part[i] - '0');
    }
    if (!ok || (k == 3 && end != text.size())) {
      throw ParameterError(option, fmt::format("expected X0,Y0,X1,Y1 (four non-negative cell "
                                               "indices), got '{}'",
                                               escape_for_message(text)));
    }
    v[k] = value;
    pos = end + 1;
  }
  return {v[0], v[1], v[2], v[3]};
}

namespace {

// Marks in `reach` (bit) every hull cell within Chebyshev radius `half` of a flyable position, by
// a 2D prefix sum of the flyable mask: O(cells) for any footprint.
void mark_reachable(const HullMask& hull, const grid::Grid<std::uint8_t>& flyable, int half,
                    std::uint8_t bit, grid::Grid<std::uint8_t>& reach) {
  const int w = hull.width();
  const int h = hull.height();
  std::vector<int> sum(static_cast<std::size_t>(w + 1) * static_cast<std::size_t>(h + 1), 0);
  auto at = [&](int x, int y) -> int& {
    return sum[static_cast<std::size_t>(y) * static_cast<std::size_t>(w + 1) +
               static_cast<std::size_t>(x)];
  };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      at(x + 1, y + 1) = at(x, y + 1) + at(x + 1, y) - at(x, y) + (flyable(x, y) ? 1 : 0);
    }
  }
  for (int i : hull.cells()) {
    const grid::Cell c = hull.mask().cell(i);
    const int x0 = std::max(0, c.x - half);
    const int x1 = std::min(w - 1, c.x + half) + 1;
    const int y0 = std::max(0, c.y - half);
    const int y1 = std::min(h - 1, c.y + half) + 1;
    if (at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0) > 0) reach[i] |= bit;
  }
}

// Flight components and which of them sees each hull cell (docs/model.md §8). The flyable
// positions are exactly those connected to a start, so every component holds a UAV; on a grid
// that closes on itself positions joined only across the seam are one component.
void label_flight_components(const HullMask& hull, std::span<const grid::Cell> starts, int half1,
                             int half2, const grid::EdgeSteps& seam, Reachability& r) {
  grid::Grid<int> labels;
  grid::BfsScratch scratch;
  const int count = grid::label_components(r.flyable, labels, scratch, seam);
  // Renumber by the lowest UAV id starting in each component.
  std::vector<int> renumber(static_cast<std::size_t>(count), -1);
  int next = 0;
  for (const grid::Cell& s : starts) {
    if (!labels.contains(s) || labels[s] < 0) continue;
    int& to = renumber[static_cast<std::size_t>(labels[s])];
    if (to < 0) to = next++;
  }
  r.flight_components = next;
  r.flight_component = grid::Grid<int>(labels.width(), labels.height(), -1);
  for (int i = 0; i < labels.size(); ++i) {
    if (labels[i] >= 0) r.flight_component[i] = renumber[static_cast<std::size_t>(labels[i])];
  }
  r.seen_from = grid::Grid<int>(labels.width(), labels.height(), -1);
  grid::DistanceService service(r.flyable, /*cached_fields=*/1);
  for (int i : hull.cells()) {
    if (r.reach[i] == 0) continue;
    const grid::Cell c = hull.mask().cell(i);
    const grid::Cell v = service.viewpoint(c, (r.reach[i] & kReachZ1) != 0 ? half1 : half2);
    r.seen_from[i] = r.flight_component[v];
  }
}

}  // namespace

Reachability compute_reachability(const HullMask& hull, const NoFlyMask* no_fly, int s1, int s2,
                                  std::span<const grid::Cell> starts) {
  Reachability r;
  const int w = hull.width();
  const int h = hull.height();
  r.flyable = grid::Grid<std::uint8_t>(w, h, 1);
  r.reach = grid::Grid<std::uint8_t>(w, h, 0);
  if (no_fly != nullptr) {
    for (std::uint8_t v : no_fly->values()) r.any_no_fly = r.any_no_fly || v != 0;
  }
  if (!r.any_no_fly) {
    for (int i : hull.cells()) r.reach[i] = kReachZ1 | kReachZ2;
    return r;
  }
  // Flyable: allowed and connected to a start (a pocket enclosed by no-fly positions is as good
  // as no-fly for every UAV), across the seam of a grid that closes on itself too.
  const grid::EdgeSteps seam = seam_links(hull);
  grid::Grid<std::uint8_t> allowed(w, h, 0);
  for (int i = 0; i < allowed.size(); ++i) allowed[i] = (*no_fly)[i] == 0 ? 1 : 0;
  std::vector<int> sources;
  for (const grid::Cell& s : starts) {
    if (allowed.contains(s) && allowed[s]) sources.push_back(allowed.index(s));
  }
  grid::Grid<int> d;
  grid::BfsScratch scratch;
  grid::bfs_distances(allowed, sources, d, scratch, seam);
  for (int i = 0; i < d.size(); ++i) r.flyable[i] = d[i] < grid::kUnreachable ? 1 : 0;
  mark_reachable(hull, r.flyable, footprint_half(s1), kReachZ1, r.reach);
  mark_reachable(hull, r.flyable, footprint_half(s2), kReachZ2, r.reach);
  for (int i : hull.cells()) {
    if ((r.reach[i] & kReachZ1) == 0) ++r.unreachable_z1;
    if ((r.reach[i] & kReachZ2) == 0) ++r.unreachable_z2;
  }
  label_flight_components(hull, starts, footprint_half(s1), footprint_half(s2), seam, r);
  return r;
}

grid::DistanceService make_distance_service(const Reachability& reach,
                                            const grid::FlightSteps& flights) {
  if (!flights.empty()) return grid::DistanceService(reach.flyable, flights.longer_plane());
  if (!reach.any_no_fly)
    return grid::DistanceService(reach.flyable.width(), reach.flyable.height());
  return grid::DistanceService(reach.flyable);
}

std::vector<int> unreachable_cells(const HullMask& hull, const Reachability& reach,
                                   std::uint8_t bit) {
  std::vector<int> out;
  for (int i : hull.cells()) {
    if ((reach.reach[i] & bit) == 0) out.push_back(i);
  }
  return out;
}

}  // namespace hullinspect::world
