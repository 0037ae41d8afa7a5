#include "hullinspect/io/trace_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <set>
#include <string_view>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/files/bounded_read.hpp"
#include "hullinspect/files/json_document.hpp"
#include "hullinspect/grid/flight_steps.hpp"
#include "hullinspect/sim/uav_rules.hpp"
#include "hullinspect/world/ship_frame_bounds.hpp"
#include "trace_checker.hpp"
#include "trace_motion.hpp"

namespace hullinspect::io {

using nlohmann::json;

namespace {

using detail::TraceChecker;
using detail::TraceMission;

// Sorted, distinct flat cell indices inside the grid.
void check_cell_set(const TraceChecker& check, const json& v, const std::string& where,
                    std::int64_t cells) {
  check.array(v, where);
  std::int64_t previous = -1;
  for (std::size_t j = 0; j < v.size(); ++j) {
    const auto at = fmt::format("{}[{}]", where, j);
    const auto c = check.integer(v[j], at, 0, cells - 1);
    if (c <= previous)
      check.fail(at, fmt::format("{} is not above the previous index {}", c, previous));
    previous = c;
  }
}

// `layers_seen`: the layers whose whole set an earlier frame gave (changes need one).
void check_frame(const TraceChecker& check, const json& f, std::size_t i, const TraceMission& m,
                 std::set<std::string>& layers_seen) {
  const int width = m.width;
  const int height = m.height;
  const auto where = fmt::format("frames[{}]", i);
  check.object(f, where);
  const auto cells = static_cast<std::int64_t>(width) * height;
  check.integer(check.field(f, where, "t"), where + ".t", static_cast<std::int64_t>(i),
                static_cast<std::int64_t>(i));

  const auto& u = check.array(check.field(f, where, "u"), where + ".u");
  if (u.size() != m.uavs * m.fields) {
    check.fail(where + ".u", fmt::format("expected {} numbers ({} per UAV), got {}",
                                         m.uavs * m.fields, m.fields, u.size()));
  }
  const auto bounds = detail::uav_value_bounds(m);
  for (std::size_t j = 0; j < u.size(); ++j) {
    const auto& [lo, hi] = bounds[j % m.fields];
    check.integer(u[j], fmt::format("{}.u[{}]", where, j), lo, hi);
  }

  const auto& c = check.array(check.field(f, where, "c"), where + ".c");
  if (c.size() % 2 != 0) check.fail(where + ".c", "expected [cell, value] pairs (an even length)");
  for (std::size_t j = 0; j < c.size(); j += 2) {
    check.integer(c[j], fmt::format("{}.c[{}]", where, j), 0, cells - 1);
    check.integer(c[j + 1], fmt::format("{}.c[{}]", where, j + 1), 0, 3);
  }

  if (auto p = f.find("p"); p != f.end()) {
    check.object(*p, where + ".p");
    const auto uavs = static_cast<int>(m.uavs);
    for (const auto& [key, a] : p->items()) {
      const auto at = fmt::format("{}.p.{}", where, key);
      int k = -1;
      const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), k);
      if (ec != std::errc() || end != key.data() + key.size() || k < 0 || k >= uavs) {
        check.fail(at, fmt::format("the key must be a UAV index in [0, {}]", uavs - 1));
      }
      check.object(a, at);
      if (!check.field(a, at, "mode").is_string()) check.fail(at + ".mode", "expected a string");
      const auto& target = check.field(a, at, "target");
      if (!target.is_null()) check.cell(target, at + ".target", width, height);
      const auto& plan = check.array(check.field(a, at, "plan"), at + ".plan");
      for (std::size_t j = 0; j < plan.size(); ++j) {
        check.cell(plan[j], fmt::format("{}.plan[{}]", at, j), width, height);
      }
    }
  }

  if (auto l = f.find("l"); l != f.end()) {
    check.object(*l, where + ".l");
    for (const auto& [name, value] : l->items()) {
      const auto at = fmt::format("{}.l.{}", where, name);
      if (value.is_array()) {
        check_cell_set(check, value, at, cells);
        layers_seen.insert(name);
        continue;
      }
      if (!value.is_object()) {
        check.fail(at,
                   "expected the layer's cells (an array) or its changes {\"add\", \"remove\"}");
      }
      if (!layers_seen.contains(name)) {
        check.fail(at, "changes to a layer whose whole set was not given before");
      }
      for (const auto& [key, part] : value.items()) {
        if (key != "add" && key != "remove")
          check.fail(at + "." + key, "unknown key (known: add, remove)");
        check_cell_set(check, part, at + "." + key, cells);
      }
    }
  }
}

// The optional `ship_frame` of a hull imported from a mesh: origin [X0, Z0], side_plane_y, side,
// and `height` rows of `width` depths (metres ≥ 0) and unit normals [nx, ny, nz]; on an unrolled
// hull (side "both") surface points [X, Y, Z] instead of depths.
void check_ship_frame(const TraceChecker& check, const json& frame, int width, int height) {
  check.object(frame, "ship_frame");
  const auto finite = [&](const json& v, const std::string& where) {
    if (!v.is_number() || !(std::abs(v.get<double>()) <= world::kMaxShipFrameM)) {
      check.fail(where, fmt::format("expected metres in [{}, {}]", -world::kMaxShipFrameM,
                                    world::kMaxShipFrameM));
    }
    return v.get<double>();
  };
  const auto& origin = check.array(check.field(frame, "ship_frame", "origin"), "ship_frame.origin");
  if (origin.size() != 2) check.fail("ship_frame.origin", "expected [X0, Z0] in metres");
  finite(origin[0], "ship_frame.origin[0]");
  finite(origin[1], "ship_frame.origin[1]");
  finite(check.field(frame, "ship_frame", "side_plane_y"), "ship_frame.side_plane_y");
  const auto& side = check.field(frame, "ship_frame", "side");
  if (side != "port" && side != "starboard" && side != "both") {
    check.fail("ship_frame.side", "expected \"port\", \"starboard\" or \"both\"");
  }
  // Checks `name` as rows of cells and each cell with `cell`.
  const auto grid_rows = [&](const char* name, auto cell) {
    const std::string where = std::string("ship_frame.") + name;
    const auto& rows = check.array(check.field(frame, "ship_frame", name), where);
    if (rows.size() != static_cast<std::size_t>(height)) {
      check.fail(where,
                 fmt::format("expected {} rows (the grid height), got {}", height, rows.size()));
    }
    for (std::size_t y = 0; y < rows.size(); ++y) {
      const auto at = fmt::format("{}[{}]", where, y);
      const auto& row = check.array(rows[y], at);
      if (row.size() != static_cast<std::size_t>(width)) {
        check.fail(at,
                   fmt::format("expected {} values (the grid width), got {}", width, row.size()));
      }
      for (std::size_t x = 0; x < row.size(); ++x) cell(row[x], fmt::format("{}[{}]", at, x));
    }
  };
  if (const auto seam = frame.find("seam"); seam != frame.end()) {
    if (!seam->is_boolean()) check.fail("ship_frame.seam", "expected true or false");
    if (*seam == true && (side != "both" || width < 3)) {
      check.fail("ship_frame.seam",
                 "expected only on an unrolled hull (side both) of 3 or more "
                 "columns");
    }
  }
  if (side == "both") {
    // An unrolled hull: per cell the surface point [X, Y, Z] a UAV there stands off from.
    grid_rows("surface", [&](const json& v, const std::string& at) {
      if (!v.is_array() || v.size() != 3) check.fail(at, "expected a point [X, Y, Z] in metres");
      for (const json& c : v) finite(c, at);
    });
  } else {
    grid_rows("depth", [&](const json& v, const std::string& at) {
      if (finite(v, at) < 0) check.fail(at, "expected metres >= 0");
    });
  }
  grid_rows("normal", [&](const json& v, const std::string& at) {
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() ||
        !v[2].is_number()) {
      check.fail(at, "expected a unit vector [nx, ny, nz]");
    }
    const double length = std::hypot(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
    if (!(std::abs(length - 1.0) < 1e-3)) check.fail(at, "expected a unit vector [nx, ny, nz]");
  });
}

}  // namespace

void validate_trace(const json& trace, const std::string& source) {
  const TraceChecker check(source);
  check.object(trace, "trace");
  const auto& format = check.field(trace, "", "format");
  if (!format.is_string() || format.get_ref<const std::string&>() != kTraceFormat) {
    check.fail("format", fmt::format("expected \"{}\" (not a hullinspect trace?)", kTraceFormat));
  }
  const auto& version = check.field(trace, "", "version");
  // Version 1 is version 2 without layer changes and version 2 is version 3 of the paper's model
  // (docs/trace-format.md "Compatibility"), so all three are read.
  if (!version.is_number_integer() || version.get<int>() < 1 ||
      version.get<int>() > kTraceVersion) {
    check.fail("version",
               fmt::format("{} is not supported (this hullinspect reads versions 1 to {})",
                           version.dump(), kTraceVersion));
  }
  check.object(check.field(trace, "", "parameters"), "parameters");

  const auto& grid = check.object(check.field(trace, "", "grid"), "grid");
  const int width =
      static_cast<int>(check.integer(check.field(grid, "grid", "width"), "grid.width", 1, 1 << 15));
  const int height = static_cast<int>(
      check.integer(check.field(grid, "grid", "height"), "grid.height", 1, 1 << 15));
  const auto& cell_size = check.field(grid, "grid", "cell_size_m");
  if (!cell_size.is_number() || !(cell_size.get<double>() >= world::kMinCellSizeM &&
                                  cell_size.get<double>() <= world::kMaxCellSizeM)) {
    check.fail("grid.cell_size_m", fmt::format("expected metres in [{}, {}]", world::kMinCellSizeM,
                                               world::kMaxCellSizeM));
  }
  if (auto camera = trace.find("camera"); camera != trace.end()) {
    check.object(*camera, "camera");
    const auto& theta = check.field(*camera, "camera", "theta_deg");
    if (!theta.is_number() || !(theta.get<double>() > 0 && theta.get<double>() < 180)) {
      check.fail("camera.theta_deg", "expected degrees in (0, 180)");
    }
  }
  const auto plane_change_steps = static_cast<int>(check.integer(
      check.field(trace, "", "plane_change_steps"), "plane_change_steps", 1, 1 << 20));
  if (auto step = trace.find("step_seconds"); step != trace.end()) {
    if (!step->is_number() || !(step->get<double>() > 0 && step->get<double>() <= 1e9)) {
      check.fail("step_seconds", "expected seconds in (0, 1e9]");
    }
  }
  const auto& footprint = check.array(check.field(trace, "", "footprint"), "footprint");
  if (footprint.size() != 2) check.fail("footprint", "expected [s1, s2]");
  const auto s1 = check.integer(footprint[0], "footprint[0]", 1, std::max(width, height) * 2 + 1);
  const auto s2 = check.integer(footprint[1], "footprint[1]", 1, std::max(width, height) * 2 + 1);
  if (auto broken = sim::footprint_violation(s1, s2)) check.fail("footprint", *broken);

  check.rows(check.field(trace, "", "truth"), "truth", width, height, ".01");
  check.rows(check.field(trace, "", "prior"), "prior", width, height, ".01");
  check.rows(check.field(trace, "", "initial_map"), "initial_map", width, height, ".0123");
  const auto& partition = check.field(trace, "", "partition");
  if (!partition.is_null()) {
    check.rows(partition, "partition", width, height, ".0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ");
  }

  if (trace.contains("ship_frame")) check_ship_frame(check, trace["ship_frame"], width, height);
  if (trace.contains("no_fly")) check.rows(trace["no_fly"], "no_fly", width, height, ".#");
  if (trace.contains("unreachable")) {
    check.rows(trace["unreachable"], "unreachable", width, height, ".dx");
  }

  const TraceMission mission =
      detail::trace_mission(check, trace, version.get<int>(), width, height, plane_change_steps);
  const auto& frames = trace["frames"];
  std::set<std::string> layers_seen;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    check_frame(check, frames[i], i, mission, layers_seen);
  }
  const auto counts = detail::check_motion(check, frames, mission);

  const auto last = static_cast<std::int64_t>(frames.size()) - 1;
  const auto& series = check.object(check.field(trace, "", "series"), "series");
  for (const char* name : {"inspected", "known"}) {
    const auto where = std::string("series.") + name;
    const auto& s = check.array(check.field(series, "series", name), where);
    if (s.size() != frames.size()) {
      check.fail(where,
                 fmt::format("expected one value per frame ({}), got {}", frames.size(), s.size()));
    }
    for (std::size_t t = 0; t < s.size(); ++t) {
      check.integer(s[t], fmt::format("{}[{}]", where, t), 0,
                    static_cast<std::int64_t>(width) * height);
    }
  }

  const auto& result = check.object(check.field(trace, "", "result"), "result");
  if (!check.field(result, "result", "complete").is_boolean()) {
    check.fail("result.complete", "expected true or false");
  }
  for (const char* name : {"T_c", "T_m"}) {
    const auto& t = check.field(result, "result", name);
    if (!t.is_null()) check.integer(t, std::string("result.") + name, 0, last);
  }
  check.integer(check.field(result, "result", "steps"), "result.steps", last, last);
  for (const char* name : {"hull_cells", "corroded_cells", "moves", "plane_changes", "hovers",
                           "redundant_observations"}) {
    check.integer(check.field(result, "result", name), std::string("result.") + name, 0,
                  std::numeric_limits<std::int64_t>::max());
  }
  detail::check_counts(check, result, mission, counts);
  // With launch sites the mission ends when every working UAV has landed (docs/model.md §12).
  if (mission.physical() && result["complete"].get<bool>()) {
    const auto& u = frames.back()["u"];
    for (std::size_t k = 0; k < mission.uavs; ++k) {
      const std::size_t o = mission.fields * k;
      if (u[o + 4] == 1 && (u[o + 5] == 1 || u[o + 7] != 0)) {
        check.fail("result.complete",
                   fmt::format("true, but UAV {} has not landed in the last frame", k));
      }
    }
  }
}

// A trace file larger than this is refused before it is read whole.
constexpr std::size_t kMaxTraceBytes = std::size_t{1} << 30;

json read_trace(const std::filesystem::path& path) {
  const std::string text = read_file(path, kMaxTraceBytes);
  const json trace = parse_json_document(text, path.string(), "a JSON trace");
  validate_trace(trace, path.string());
  return trace;
}

}  // namespace hullinspect::io
