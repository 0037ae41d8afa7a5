#pragma once
// The user's own corrosion maps (docs/hulls.md "Your own maps"): a prior C′ (expected corrosion)
// and/or a ground truth C (a known case to replay) replacing the generated ones.

#include <filesystem>
#include <memory>
#include <string>

#include "hullinspect/grid/grid.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/instance.hpp"

namespace hullinspect::world {

/// A corrosion map over a hull: -1 not hull, 0 clean, 1 corroded (the paper's matrix values).
struct CorrosionMap {
  std::string source;  ///< the file it was read from
  grid::Grid<std::int8_t> cells;
};

/// Reads a map in any hull-mask format (text or PGM; marked cells are corroded) and checks it
/// against `hull`: same size, no corroded cell outside the hull. Throws InputError naming the
/// file (and the cell as (x, y)).
CorrosionMap load_corrosion_map(const std::filesystem::path& path, const HullMask& hull);

/// The maps that replace the generated ones; either may be absent.
struct UserMaps {
  std::shared_ptr<const CorrosionMap> prior;
  std::shared_ptr<const CorrosionMap> truth;
  bool empty() const { return !prior && !truth; }
};

/// Loads the maps named by the (possibly empty) paths.
UserMaps load_user_maps(const std::string& prior_path, const std::string& truth_path,
                        const HullMask& hull);

/// Replaces C′ and/or C of `instance`. A replaced map's centre counts are set to 0 (it has no
/// generated centres).
void apply(const UserMaps& maps, Instance& instance);

}  // namespace hullinspect::world
