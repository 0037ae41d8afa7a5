#include "hullinspect/io/waypoints.hpp"

#include <array>

namespace hullinspect::io {

namespace {
constexpr std::array<std::string_view, 5> kActionNames = {"start", "move", "plane-change", "hold",
                                                          "transit"};
}  // namespace

std::string_view to_string(WaypointAction action) {
  return kActionNames[static_cast<std::size_t>(action)];
}

bool parse_waypoint_action(std::string_view text, WaypointAction& action) {
  for (std::size_t i = 0; i < kActionNames.size(); ++i) {
    if (kActionNames[i] == text) {
      action = static_cast<WaypointAction>(i);
      return true;
    }
  }
  return false;
}

std::vector<std::vector<GridState>> trace_states(const nlohmann::json& trace) {
  const auto& frames = trace.at("frames");
  // Values per UAV: the paper's five, eight with launch sites (docs/trace-format.md).
  const std::size_t fields = trace.contains("uav_fields") ? trace["uav_fields"].size() : 5;
  // The launch fields' offsets, when the trace has them.
  std::size_t airborne = fields, away = fields;
  if (const auto names = trace.find("uav_fields"); names != trace.end()) {
    for (std::size_t i = 0; i < names->size(); ++i) {
      if ((*names)[i] == "airborne") airborne = i;
      if ((*names)[i] == "away_left") away = i;
    }
  }
  const std::size_t uavs = frames.at(0).at("u").size() / fields;
  std::vector<std::vector<GridState>> states(uavs);
  for (auto& s : states) s.reserve(frames.size());
  for (const auto& f : frames) {
    const auto& u = f.at("u");
    for (std::size_t k = 0; k < uavs; ++k) {
      const std::size_t o = fields * k;
      GridState s;
      s.pos = {u[o].get<int>(), u[o + 1].get<int>()};
      s.z = u[o + 2].get<int>();
      s.in_transit = u[o + 3].get<int>() > 0;
      s.active = u[o + 4].get<int>() != 0;
      if (airborne < fields) s.airborne = u[o + airborne].get<int>() != 0;
      if (away < fields) s.away = !s.airborne || u[o + away].get<int>() > 0;
      states[k].push_back(s);
    }
  }
  return states;
}

std::vector<GridWaypoint> compress_trajectory(std::span<const GridState> states,
                                              const SameSurface& same_surface) {
  std::vector<GridWaypoint> out;
  if (states.empty()) return out;
  out.push_back({0, states[0].pos, states[0].z, WaypointAction::kStart, 0});

  // The segment being merged: its kind, direction (for moves) and start time.
  enum class Kind { kNone, kMove, kHold, kTransit };
  Kind kind = Kind::kNone;
  grid::Cell direction{0, 0};
  int begin = 0;
  auto flush = [&](int t) {
    if (kind == Kind::kMove || kind == Kind::kHold) {
      const auto& s = states[static_cast<std::size_t>(t)];
      out.push_back({t, s.pos, s.z,
                     kind == Kind::kMove ? WaypointAction::kMove : WaypointAction::kHold,
                     t - begin});
    }
    kind = Kind::kNone;
  };

  for (std::size_t i = 1; i < states.size(); ++i) {
    const auto& a = states[i - 1];
    const auto& b = states[i];
    const int t = static_cast<int>(i);
    if (!b.active) break;  // a failed UAV flies no further
    if (b.in_transit || b.z != a.z) {
      // A plane change: from the last frame on a plane to the first frame on the new one.
      if (kind != Kind::kTransit) {
        flush(t - 1);
        kind = Kind::kTransit;
        begin = t - 1;
      }
      if (!b.in_transit) {
        out.push_back({t, b.pos, b.z, WaypointAction::kPlaneChange, t - begin});
        kind = Kind::kNone;
      }
      continue;
    }
    if (b.pos == a.pos) {
      if (kind != Kind::kHold) {
        flush(t - 1);
        kind = Kind::kHold;
        begin = t - 1;
      }
      continue;
    }
    const grid::Cell d{b.pos.x - a.pos.x, b.pos.y - a.pos.y};
    const bool extends =
        kind == Kind::kMove && d == direction &&
        (!same_surface || same_surface(states[static_cast<std::size_t>(begin)].pos, b.pos));
    if (!extends) {
      flush(t - 1);
      kind = Kind::kMove;
      direction = d;
      begin = t - 1;
    }
  }
  // The last segment ends at the last frame the UAV was active.
  int last = static_cast<int>(states.size()) - 1;
  while (last > 0 && !states[static_cast<std::size_t>(last)].active) --last;
  if (kind == Kind::kTransit) {
    // A mission ending mid-change: the UAV is still between planes; keep its last plane state.
    kind = Kind::kNone;
  }
  flush(last);
  return out;
}

}  // namespace hullinspect::io
