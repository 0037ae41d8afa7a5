#include "hullinspect/io/trace_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "hullinspect/io/trace_reader.hpp"
#include "hullinspect/version.hpp"
#include "hullinspect/world/standoff_surface.hpp"

namespace hullinspect::io {

using nlohmann::json;

namespace {

// Rows of a matrix as strings, rows[y] with y = 0 the bottom; `symbol` maps a value to a character.
template <class T, class F>
json rows(const grid::Grid<T>& m, F symbol) {
  json out = json::array();
  for (int y = 0; y < m.height(); ++y) {
    std::string row;
    row.reserve(static_cast<std::size_t>(m.width()));
    for (int x = 0; x < m.width(); ++x) row += symbol(m(x, y));
    out.push_back(std::move(row));
  }
  return out;
}

// Metres and unit vectors to the precision of a hull JSON (0.1 mm, 1e-6): enough to place a
// waypoint to the export's 0.1 mm, and short enough for a 50 000-cell hull.
// (Divided, not multiplied, by the scale: 0.09 prints as 0.09, not 0.09000000000000001.)
double rounded(double v, double scale) {
  return std::round(v * scale) / scale;
}

// Where a hull imported from a mesh sits in the ship frame (docs/trace-format.md `ship_frame`):
// the grid's origin, the side plane, and per cell the surface's depth and outward normal. An
// unrolled hull has no side plane: per grid position the surface point a UAV there stands off
// from, and its normal, replace the depth.
json ship_frame(const world::HullGeometry& g) {
  const bool unrolled = g.unrolled();
  // Unrolled: rounded as the simulator's neighbour flights read them; empty for one side.
  const grid::StandoffPoints standoff = world::standoff_points(g);
  json placement = json::array();  // depth or surface rows
  json normal = json::array();
  for (int y = 0; y < g.height(); ++y) {
    json p = json::array();
    json n = json::array();
    for (int x = 0; x < g.width(); ++x) {
      if (unrolled) {
        p.push_back(standoff.point(x, y));
        n.push_back(standoff.normal(x, y));
        continue;
      }
      p.push_back(rounded(g.depth(x, y), 1e4));
      const world::Normal v = g.normal(x, y);
      n.push_back({rounded(v.x, 1e6), rounded(v.y, 1e6), rounded(v.z, 1e6)});
    }
    placement.push_back(std::move(p));
    normal.push_back(std::move(n));
  }
  json frame = {{"origin", {g.x0, g.z0}},
                {"side_plane_y", g.side_plane_y},
                {"side", world::to_string(g.side)},
                {"normal", std::move(normal)}};
  frame[unrolled ? "surface" : "depth"] = std::move(placement);
  // A grid that closes on itself: its seam is a neighbour flight the trace checker replays.
  if (g.seam) frame["seam"] = true;
  return frame;
}

char matrix_symbol(std::int8_t v) {
  return v < 0 ? '.' : static_cast<char>('0' + v);
}

// `physical`: the mission has launch sites, so each UAV also records whether it is airborne, its
// battery and its steps away (kPhysicalUavFields); the paper's model keeps the five fields.
json uav_states(const sim::Simulator& sim, bool physical) {
  json u = json::array();
  for (const auto& s : sim.uavs()) {
    u.push_back(s.pos.x);
    u.push_back(s.pos.y);
    u.push_back(s.z);
    u.push_back(s.transit_left);
    u.push_back(s.failed ? 0 : 1);
    if (!physical) continue;
    u.push_back(s.airborne ? 1 : 0);
    u.push_back(s.battery_left);
    u.push_back(s.away_left);
  }
  return u;
}

// The rules of the physical mission a reader checks the frames against (docs/trace-format.md):
// the launch sites and each UAV's, the legs' steps, the battery in steps and the separation.
void physical_mission(json& trace, const sim::Simulator& sim) {
  if (const auto& legs = sim.launch_legs(); !legs.empty()) {
    json sites = json::array();
    for (const auto& c : legs.sites) sites.push_back({c.x, c.y});
    trace["launch"] = {{"sites", std::move(sites)},
                       {"site_of", legs.site_of},
                       {"takeoff_steps", legs.takeoff_steps},
                       {"transfer_steps", legs.transfer_steps}};
  }
  if (const auto& b = sim.battery(); b.limited) {
    trace["battery"] = {
        {"endurance_steps", b.endurance}, {"reserve_steps", b.reserve}, {"swap_steps", b.swap}};
  }
  if (sim.params().separation > 0) trace["separation"] = sim.params().separation;
}

}  // namespace

TraceRecorder::TraceRecorder(const world::Instance& instance, json parameters)
    : instance_(instance) {
  trace_["format"] = "hullinspect-trace";
  trace_["version"] = kTraceVersion;
  trace_["generator"] = std::string("hullinspect ") + kVersion;
  trace_["parameters"] = std::move(parameters);
}

void TraceRecorder::uav(int k, std::string_view mode, grid::Cell target,
                        std::span<const grid::Cell> plan) {
  json a;
  a["mode"] = mode;
  a["target"] = target.x < 0 ? json(nullptr) : json::array({target.x, target.y});
  json p = json::array();
  for (const auto& c : plan) p.push_back(json::array({c.x, c.y}));
  a["plan"] = std::move(p);
  auto uk = static_cast<std::size_t>(k);
  if (last_uav_.size() <= uk) last_uav_.resize(uk + 1);
  if (last_uav_[uk] != a) {
    pending_uavs_[std::to_string(k)] = a;
    last_uav_[uk] = std::move(a);
  }
}

void TraceRecorder::cells(std::string_view layer, std::span<const int> indices) {
  sorted_.assign(indices.begin(), indices.end());
  std::sort(sorted_.begin(), sorted_.end());
  auto it = std::find_if(last_layers_.begin(), last_layers_.end(),
                         [&](const LayerState& l) { return l.name == layer; });
  if (it == last_layers_.end()) {
    last_layers_.push_back({std::string(layer), {}, -1});
    it = std::prev(last_layers_.end());
  }
  if (it->last_full >= 0 && it->cells == sorted_) return;
  added_.clear();
  removed_.clear();
  std::set_difference(sorted_.begin(), sorted_.end(), it->cells.begin(), it->cells.end(),
                      std::back_inserter(added_));
  std::set_difference(it->cells.begin(), it->cells.end(), sorted_.begin(), sorted_.end(),
                      std::back_inserter(removed_));
  // The whole set on the layer's first appearance, when the last whole set is a keyframe interval
  // old, or when it is no longer than the change.
  const bool full = it->last_full < 0 || frame_index_ - it->last_full >= kLayerKeyframeInterval ||
                    sorted_.size() <= added_.size() + removed_.size();
  if (full) {
    pending_layers_[std::string(layer)] = sorted_;
    it->last_full = frame_index_;
  } else {
    pending_layers_[std::string(layer)] = {{"add", added_}, {"remove", removed_}};
  }
  it->cells.swap(sorted_);
}

json TraceRecorder::frame(const sim::Simulator& sim, const planners::Planner& planner) {
  json f;
  frame_index_ = sim.time();
  f["t"] = sim.time();
  f["u"] = uav_states(sim, physical_);
  json changes = json::array();
  for (int i : sim.changed_cells()) {
    changes.push_back(i);
    changes.push_back(sim.map()[i]);
  }
  f["c"] = std::move(changes);
  pending_uavs_ = json::object();
  pending_layers_ = json::object();
  planner.annotate(*this);
  if (!pending_uavs_.empty()) f["p"] = std::move(pending_uavs_);
  if (!pending_layers_.empty()) f["l"] = std::move(pending_layers_);
  return f;
}

void TraceRecorder::on_start(const sim::Simulator& sim, const planners::Planner& planner) {
  const auto& hull = sim.hull();
  trace_["grid"] = {{"width", hull.width()},
                    {"height", hull.height()},
                    {"cell_size_m", sim.params().cell_size_m}};
  trace_["plane_change_steps"] = sim.plane_change_steps();
  // A step's seconds with --speed (docs/trace-format.md); absent: one second, the paper's model.
  if (sim.params().speed_m_s) trace_["step_seconds"] = sim.params().step_seconds();
  trace_["footprint"] = {sim.params().s1, sim.params().s2};
  physical_ = !sim.launch_legs().empty();
  physical_mission(trace_, sim);
  // The aperture places the planes in metres (stand-off ζ_z, docs/export.md).
  trace_["camera"] = {{"theta_deg", sim.params().theta_deg}};
  // A hull from a mesh: its surface stands out from the side plane by depth(x, y), which exports
  // add to the stand-off (docs/model.md "Frames and exports"). Absent for a plain mask.
  // An unrolled hull has no single side plane: its frame carries the surface points instead.
  if (const auto* g = hull.geometry()) {
    trace_["ship_frame"] = ship_frame(*g);
  }
  trace_["truth"] = rows(instance_.truth, matrix_symbol);
  trace_["prior"] = rows(instance_.prior, matrix_symbol);
  if (const auto* p = planner.partition()) {
    trace_["partition"] = rows(p->owner, [](std::int16_t v) {
      return v < 0 ? '.' : static_cast<char>(v < 10 ? '0' + v : 'A' + (v - 10));
    });
  } else {
    trace_["partition"] = nullptr;
  }
  // No-fly zones (docs/model.md): '#' no-fly positions; per hull cell 'd' when only z = 2 sees it
  // (never inspectable), 'x' when no footprint does. Absent without no-fly zones.
  if (const auto& reach = sim.reachability(); reach.any_no_fly) {
    grid::Grid<std::int8_t> no_fly(hull.width(), hull.height(), 0);
    grid::Grid<std::int8_t> unreachable(hull.width(), hull.height(), 0);
    for (int i = 0; i < no_fly.size(); ++i) {
      no_fly[i] = sim.no_fly(no_fly.cell(i)) ? 1 : 0;
      if (!hull.is_hull(i)) continue;
      if ((reach.reach[i] & world::kReachZ2) == 0) {
        unreachable[i] = 2;
      } else if ((reach.reach[i] & world::kReachZ1) == 0) {
        unreachable[i] = 1;
      }
    }
    trace_["no_fly"] = rows(no_fly, [](std::int8_t v) { return v != 0 ? '#' : '.'; });
    trace_["unreachable"] =
        rows(unreachable, [](std::int8_t v) { return v == 2 ? 'x' : (v == 1 ? 'd' : '.'); });
  }
  // The map before t = 0's sensing is the prior; frame 0 holds the changes of t = 0's sensing.
  json map0 = rows(sim.map(), matrix_symbol);
  for (int i : sim.changed_cells()) {
    const auto c = sim.map().cell(i);
    map0[static_cast<std::size_t>(c.y)].get_ref<std::string&>()[static_cast<std::size_t>(c.x)] =
        matrix_symbol(instance_.prior[i] == 1 ? sim::kCorrosionSeen : sim::kUnknown);
  }
  trace_["initial_map"] = std::move(map0);
  steps_ = json::array();
  steps_.push_back(frame(sim, planner));
}

void TraceRecorder::on_step(const sim::Simulator& sim, const planners::Planner& planner) {
  steps_.push_back(frame(sim, planner));
}

json TraceRecorder::finish(const sim::MissionResult& result) const {
  json t = trace_;
  t["uav_fields"] = physical_ ? json(kPhysicalUavFields) : json(kPaperUavFields);
  t["frames"] = steps_;
  t["series"] = {{"inspected", result.inspected_series}, {"known", result.known_series}};
  json r;
  r["complete"] = result.complete;
  r["T_c"] = result.t_c ? json(*result.t_c) : json(nullptr);
  r["T_m"] = result.t_m ? json(*result.t_m) : json(nullptr);
  r["steps"] = result.steps;
  r["hull_cells"] = result.hull_cells;
  r["corroded_cells"] = result.corroded_cells;
  r["unreachable_cells"] = result.unreachable_cells;
  r["unreachable_z2_cells"] = result.unreachable_z2_cells;
  const auto total = result.totals();
  r["moves"] = total.moves;
  r["plane_changes"] = total.plane_changes;
  r["hovers"] = total.hovers;
  r["redundant_observations"] = result.redundant_observations;
  // Only a mission with launch sites flies sorties, and only one with a battery can crash.
  if (physical_) {
    r["sorties"] = result.sorties();
    r["flight_steps"] = total.flight_steps;
  }
  if (trace_.contains("battery")) r["battery_crashes"] = result.battery_crashes;
  // Only a mission with a separation D measures it (docs/trace-format.md).
  // min_separation only once two UAVs have been airborne together.
  if (trace_.contains("separation")) {
    r["separation_conflicts"] = result.separation_conflicts;
    if (result.min_separation) r["min_separation"] = *result.min_separation;
  }
  t["result"] = std::move(r);
  return t;
}

}  // namespace hullinspect::io
