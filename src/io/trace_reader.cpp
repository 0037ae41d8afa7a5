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

namespace hullinspect::io {

using nlohmann::json;

namespace {

constexpr std::size_t kUavFields = 5;  // x, y, z, transit_left, active

// Checks one trace; every failure names the field, e.g. "frames[3].u[7]: expected 1 or 2".
class TraceChecker {
 public:
  explicit TraceChecker(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
    throw InputError(source_, 0, where + ": " + problem);
  }

  const json& field(const json& object, const std::string& where, const char* key) const {
    auto it = object.find(key);
    if (it == object.end()) fail(where.empty() ? key : where + "." + key, "missing");
    return *it;
  }

  std::int64_t integer(const json& v, const std::string& where, std::int64_t lo,
                       std::int64_t hi) const {
    if (!v.is_number_integer()) fail(where, "expected an integer");
    if (v.is_number_unsigned() &&
        v.get<std::uint64_t>() >
            static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
      fail(where, fmt::format("{} is outside [{}, {}]", v.dump(), lo, hi));
    }
    const auto i = v.get<std::int64_t>();
    if (i < lo || i > hi) fail(where, fmt::format("{} is outside [{}, {}]", i, lo, hi));
    return i;
  }

  const json& array(const json& v, const std::string& where) const {
    if (!v.is_array()) fail(where, "expected an array");
    return v;
  }

  const json& object(const json& v, const std::string& where) const {
    if (!v.is_object()) fail(where, "expected an object");
    return v;
  }

  // `height` strings of `width` characters from `alphabet`.
  void rows(const json& v, const std::string& where, int width, int height,
            std::string_view alphabet) const {
    array(v, where);
    if (v.size() != static_cast<std::size_t>(height)) {
      fail(where, fmt::format("expected {} rows (the grid height), got {}", height, v.size()));
    }
    for (std::size_t y = 0; y < v.size(); ++y) {
      const auto at = fmt::format("{}[{}]", where, y);
      if (!v[y].is_string()) fail(at, "expected a string");
      const auto& row = v[y].get_ref<const std::string&>();
      if (row.size() != static_cast<std::size_t>(width)) {
        fail(at, fmt::format("expected {} characters (the grid width), got {}", width, row.size()));
      }
      for (std::size_t x = 0; x < row.size(); ++x) {
        if (alphabet.find(row[x]) == std::string_view::npos) {
          fail(at,
               fmt::format("character {} is '{}', expected one of \"{}\"", x, row[x], alphabet));
        }
      }
    }
  }

  void cell(const json& v, const std::string& where, int width, int height) const {
    if (!v.is_array() || v.size() != 2) fail(where, "expected [x, y]");
    integer(v[0], where + "[0]", 0, width - 1);
    integer(v[1], where + "[1]", 0, height - 1);
  }

 private:
  std::string source_;
};

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
void check_frame(const TraceChecker& check, const json& f, std::size_t i, int width, int height,
                 std::size_t uav_values, std::set<std::string>& layers_seen) {
  const auto where = fmt::format("frames[{}]", i);
  check.object(f, where);
  const auto cells = static_cast<std::int64_t>(width) * height;
  check.integer(check.field(f, where, "t"), where + ".t", static_cast<std::int64_t>(i),
                static_cast<std::int64_t>(i));

  const auto& u = check.array(check.field(f, where, "u"), where + ".u");
  if (u.size() != uav_values) {
    check.fail(where + ".u", fmt::format("expected {} numbers ({} per UAV), got {}", uav_values,
                                         kUavFields, u.size()));
  }
  // Bounds of x, y, z, transit_left, active.
  const std::array<std::int64_t, kUavFields> lo = {0, 0, 1, 0, 0};
  const std::array<std::int64_t, kUavFields> hi = {width - 1, height - 1, 2, 1 << 20, 1};
  for (std::size_t j = 0; j < u.size(); ++j) {
    check.integer(u[j], fmt::format("{}.u[{}]", where, j), lo[j % kUavFields], hi[j % kUavFields]);
  }

  const auto& c = check.array(check.field(f, where, "c"), where + ".c");
  if (c.size() % 2 != 0) check.fail(where + ".c", "expected [cell, value] pairs (an even length)");
  for (std::size_t j = 0; j < c.size(); j += 2) {
    check.integer(c[j], fmt::format("{}.c[{}]", where, j), 0, cells - 1);
    check.integer(c[j + 1], fmt::format("{}.c[{}]", where, j + 1), 0, 3);
  }

  if (auto p = f.find("p"); p != f.end()) {
    check.object(*p, where + ".p");
    const auto uavs = static_cast<int>(uav_values / kUavFields);
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

// "[json.exception.parse_error.101] parse error at line 3, column 1: syntax error …" → the part
// after the location, on one line.

}  // namespace

// The model's motion rules (sim/uav_rules.hpp) over every UAV of every frame, and no UAV on a
// no-fly position ('#' in `no_fly`, already checked against the grid). Frames are checked.
// A trace does not record a UAV's flight to a distant neighbour (docs/model.md "Neighbour
// flights"): after a move of k steps in `flights`, the UAV is checked to stay put for k − 1 frames.
void check_motion(const TraceChecker& check, const json& frames, int plane_change_steps,
                  const json* no_fly, bool away_unrecorded, const grid::FlightSteps& flights) {
  const auto state = [](const json& u, std::size_t k) {
    sim::UavState s;
    s.pos = {u[kUavFields * k].get<int>(), u[kUavFields * k + 1].get<int>()};
    s.z = u[kUavFields * k + 2].get<int>();
    s.transit_left = u[kUavFields * k + 3].get<int>();
    s.failed = u[kUavFields * k + 4].get<int>() == 0;
    return s;
  };
  const std::size_t uavs = frames[0]["u"].size() / kUavFields;
  std::vector<int> flight_left(uavs, 0);  // per UAV, after the previous frame
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto& u = frames[i]["u"];
    for (std::size_t k = 0; k < uavs; ++k) {
      const auto where = fmt::format("frames[{}].u", i);
      sim::UavState now = state(u, k);
      if (auto broken = sim::state_violation(now, plane_change_steps)) {
        check.fail(where, fmt::format("UAV {} {}", k, *broken));
      }
      if (no_fly != nullptr) {
        const auto& row =
            (*no_fly)[static_cast<std::size_t>(now.pos.y)].get_ref<const std::string&>();
        if (row[static_cast<std::size_t>(now.pos.x)] == '#') {
          check.fail(where, fmt::format("UAV {} is on the no-fly position ({}, {})", k, now.pos.x,
                                        now.pos.y));
        }
      }
      if (i == 0) continue;
      sim::UavState before = state(frames[i - 1]["u"], k);
      // A trace of a mission with launch sites does not record when a UAV is away at its site
      // (docs/trace-format.md): such a step is checked as the simulator flies it.
      if (away_unrecorded) before.away_left = 1;
      before.flight_left = flight_left[k];
      if (now.failed || before.flight_left > 0) {
        now.flight_left = before.flight_left - (now.failed ? 0 : 1);
      } else if (!away_unrecorded && grid::adjacent(before.pos, now.pos, flights.plane[0])) {
        now.flight_left = flights.between(before.pos, now.pos, before.z) - 1;
      }
      flight_left[k] = now.flight_left;
      if (auto broken = sim::step_violation(before, now, plane_change_steps, flights)) {
        check.fail(where, fmt::format("UAV {} {} (from frame {})", k, *broken, i - 1));
      }
    }
  }
}

// The neighbour flights of a trace of an unrolled hull, from its checked `ship_frame`, grid, camera
// and footprint by the simulator's own function over the same numbers; empty for any other hull.
grid::FlightSteps trace_flights(const json& trace, int width, int height) {
  const auto frame = trace.find("ship_frame");
  if (frame == trace.end() || (*frame)["side"] != "both") return {};
  grid::StandoffPoints points;
  points.point = grid::Grid<std::array<double, 3>>(width, height);
  points.normal = grid::Grid<std::array<double, 3>>(width, height);
  const json& surface = (*frame)["surface"];
  const json& normal = (*frame)["normal"];
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const json& p = surface[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)];
      const json& n = normal[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)];
      points.point(x, y) = {p[0].get<double>(), p[1].get<double>(), p[2].get<double>()};
      points.normal(x, y) = {n[0].get<double>(), n[1].get<double>(), n[2].get<double>()};
    }
  }
  points.seam = frame->value("seam", false);
  const double theta = trace.contains("camera") ? trace["camera"]["theta_deg"].get<double>() : 90.0;
  return grid::flight_steps(points, trace["grid"]["cell_size_m"].get<double>(), theta,
                            trace["footprint"][0].get<int>(), trace["footprint"][1].get<int>());
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

void validate_trace(const json& trace, const std::string& source) {
  const TraceChecker check(source);
  check.object(trace, "trace");
  const auto& format = check.field(trace, "", "format");
  if (!format.is_string() || format.get_ref<const std::string&>() != kTraceFormat) {
    check.fail("format", fmt::format("expected \"{}\" (not a hullinspect trace?)", kTraceFormat));
  }
  const auto& version = check.field(trace, "", "version");
  // Version 1 is version 2 without layer changes, so both are read.
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

  const auto& frames = check.array(check.field(trace, "", "frames"), "frames");
  if (frames.empty()) check.fail("frames", "expected at least frame 0 (t = 0)");
  const auto& u0 = check.array(check.field(check.object(frames[0], "frames[0]"), "frames[0]", "u"),
                               "frames[0].u");
  if (u0.empty() || u0.size() % kUavFields != 0) {
    check.fail("frames[0].u",
               fmt::format("expected {} numbers per UAV, got {} in all", kUavFields, u0.size()));
  }
  std::set<std::string> layers_seen;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    check_frame(check, frames[i], i, width, height, u0.size(), layers_seen);
  }
  const bool away_unrecorded = trace.contains("parameters") && trace["parameters"].is_object() &&
                               trace["parameters"].contains("launch");
  check_motion(check, frames, plane_change_steps,
               trace.contains("no_fly") ? &trace["no_fly"] : nullptr, away_unrecorded,
               trace_flights(trace, width, height));

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
