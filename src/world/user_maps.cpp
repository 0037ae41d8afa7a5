#include "hullinspect/world/user_maps.hpp"

#include <fmt/format.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/cell_map.hpp"

namespace hullinspect::world {

CorrosionMap load_corrosion_map(const std::filesystem::path& path, const HullMask& hull) {
  const std::string source = path.string();
  const grid::Grid<std::uint8_t> marked = load_cell_map(path);
  if (marked.width() != hull.width() || marked.height() != hull.height()) {
    throw InputError(source, 0,
                     fmt::format("the map is {} × {} but the hull ({}) is {} × {}", marked.width(),
                                 marked.height(), hull.source(), hull.width(), hull.height()));
  }
  CorrosionMap map{source, grid::Grid<std::int8_t>(hull.width(), hull.height(), -1)};
  for (int y = 0; y < hull.height(); ++y) {
    for (int x = 0; x < hull.width(); ++x) {
      if (marked(x, y) && !hull.is_hull(x, y)) {
        throw InputError(source, 0,
                         fmt::format("cell ({}, {}) is corroded but not part of the hull", x, y));
      }
      if (hull.is_hull(x, y)) map.cells(x, y) = marked(x, y) ? 1 : 0;
    }
  }
  return map;
}

UserMaps load_user_maps(const std::string& prior_path, const std::string& truth_path,
                        const HullMask& hull) {
  UserMaps maps;
  if (!prior_path.empty()) {
    maps.prior = std::make_shared<const CorrosionMap>(load_corrosion_map(prior_path, hull));
  }
  if (!truth_path.empty()) {
    maps.truth = std::make_shared<const CorrosionMap>(load_corrosion_map(truth_path, hull));
  }
  return maps;
}

void apply(const UserMaps& maps, Instance& instance) {
  const auto check = [&](const CorrosionMap& m) {
    if (m.cells.width() != instance.truth.width() || m.cells.height() != instance.truth.height()) {
      throw LogicError(fmt::format("{}: map does not match the instance's grid", m.source));
    }
  };
  if (maps.prior) {
    check(*maps.prior);
    instance.prior = maps.prior->cells;
    instance.prior_true_positive_centres = 0;
    instance.prior_false_positive_centres = 0;
  }
  if (maps.truth) {
    check(*maps.truth);
    instance.truth = maps.truth->cells;
    instance.truth_centres = 0;
  }
}

}  // namespace hullinspect::world
