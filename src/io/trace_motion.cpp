#include "trace_motion.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "hullinspect/core/plural.hpp"
#include "hullinspect/io/trace_reader.hpp"
#include "hullinspect/sim/uav_rules.hpp"

namespace hullinspect::io::detail {

using nlohmann::json;

namespace {

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

template <std::size_t N>
json field_names(const std::array<const char*, N>& names) {
  json out = json::array();
  for (const char* n : names) out.push_back(n);
  return out;
}

// The `launch` object: sites on the grid (not checked against the hull: the writer did), the site
// of every UAV, the take-off and transfer steps.
void read_launch(const TraceChecker& check, const json& launch, TraceMission& m) {
  check.object(launch, "launch");
  const auto& sites = check.array(check.field(launch, "launch", "sites"), "launch.sites");
  if (sites.empty()) check.fail("launch.sites", "expected at least one site [x, y]");
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const auto at = fmt::format("launch.sites[{}]", i);
    check.cell(sites[i], at, m.width, m.height);
    m.sites.push_back({sites[i][0].get<int>(), sites[i][1].get<int>()});
  }
  const auto& site_of = check.array(check.field(launch, "launch", "site_of"), "launch.site_of");
  if (site_of.size() != m.uavs) {
    check.fail("launch.site_of",
               fmt::format("expected one site per UAV ({}), got {}", m.uavs, site_of.size()));
  }
  for (std::size_t k = 0; k < site_of.size(); ++k) {
    m.site_of.push_back(static_cast<int>(check.integer(
        site_of[k], fmt::format("launch.site_of[{}]", k), 0, std::ssize(m.sites) - 1)));
  }
  for (const char* name : {"takeoff_steps", "transfer_steps"}) {
    check.integer(check.field(launch, "launch", name), std::string("launch.") + name, 0, 1 << 30);
  }
}

void read_battery(const TraceChecker& check, const json& battery, TraceMission& m) {
  check.object(battery, "battery");
  m.battery = true;
  m.endurance = static_cast<int>(check.integer(check.field(battery, "battery", "endurance_steps"),
                                               "battery.endurance_steps", 1, 1 << 30));
  m.reserve = static_cast<int>(check.integer(check.field(battery, "battery", "reserve_steps"),
                                             "battery.reserve_steps", 0, m.endurance - 1));
  m.swap = static_cast<int>(check.integer(check.field(battery, "battery", "swap_steps"),
                                          "battery.swap_steps", 0, 1 << 30));
}

// One UAV's values at offset `k` of a frame's `u` (already checked against its bounds).
sim::UavState uav_state(const json& u, std::size_t k, const TraceMission& m) {
  const std::size_t o = m.fields * k;
  sim::UavState s;
  s.pos = {u[o].get<int>(), u[o + 1].get<int>()};
  s.z = u[o + 2].get<int>();
  s.transit_left = u[o + 3].get<int>();
  s.failed = u[o + 4].get<int>() == 0;
  if (m.physical()) {
    s.airborne = u[o + 5].get<int>() == 1;
    s.battery_left = u[o + 6].get<int>();
    s.away_left = u[o + 7].get<int>();
  }
  return s;
}

std::string at(grid::Cell c) {
  return fmt::format("({}, {})", c.x, c.y);
}

}  // namespace

TraceMission trace_mission(const TraceChecker& check, const json& trace, int version, int width,
                           int height, int plane_change_steps) {
  TraceMission m;
  m.width = width;
  m.height = height;
  m.plane_change_steps = plane_change_steps;
  const bool physical = version >= 3 && trace.contains("launch");
  const json paper = field_names(kPaperUavFields);
  const json expected = physical ? field_names(kPhysicalUavFields) : paper;
  // Traces before version 3 may lack the field; they hold the paper's five values per UAV.
  if (auto fields = trace.find("uav_fields"); fields != trace.end() || version >= 3) {
    if (fields == trace.end() || *fields != expected) {
      check.fail("uav_fields", fmt::format("expected {}{}", expected.dump(),
                                           physical ? " (a mission with launch sites)" : ""));
    }
  }
  m.fields = expected.size();

  const auto& frames = check.array(check.field(trace, "", "frames"), "frames");
  if (frames.empty()) check.fail("frames", "expected at least frame 0 (t = 0)");
  const auto& u0 = check.array(check.field(check.object(frames[0], "frames[0]"), "frames[0]", "u"),
                               "frames[0].u");
  if (u0.empty() || u0.size() % m.fields != 0) {
    check.fail("frames[0].u",
               fmt::format("expected {} numbers per UAV, got {} in all", m.fields, u0.size()));
  }
  m.uavs = u0.size() / m.fields;

  if (trace.contains("no_fly")) m.no_fly = &trace["no_fly"];
  m.flights = trace_flights(trace, width, height);
  if (version < 3) {
    // Version 2 wrote a mission with launch sites without recording when a UAV is away.
    m.away_unrecorded = trace["parameters"].contains("launch");
    return m;
  }
  // Version 3 recorded the climb before a flight home on the plane climbed from until the first
  // move away.
  m.climb_recorded_at_move = version < 4;
  if (physical) read_launch(check, trace["launch"], m);
  if (auto battery = trace.find("battery"); battery != trace.end()) {
    if (!physical) check.fail("battery", "a battery needs launch sites (\"launch\")");
    read_battery(check, *battery, m);
  }
  if (auto d = trace.find("separation"); d != trace.end()) {
    m.separation = static_cast<int>(check.integer(*d, "separation", 1, std::int64_t{1} << 30));
  }
  return m;
}

std::vector<std::pair<std::int64_t, std::int64_t>> uav_value_bounds(const TraceMission& m) {
  std::vector<std::pair<std::int64_t, std::int64_t>> b = {
      {0, m.width - 1}, {0, m.height - 1}, {1, 2}, {0, 1 << 20}, {0, 1}};
  if (m.physical()) {
    b.emplace_back(0, 1);  // airborne
    b.emplace_back(m.battery ? 0 : -1, m.battery ? m.endurance : -1);
    b.emplace_back(0, 1 << 30);  // away_left
  }
  return b;
}

TraceCounts check_motion(const TraceChecker& check, const json& frames, const TraceMission& m) {
  TraceCounts counts;
  std::vector<sim::UavState> before(m.uavs);
  std::vector<sim::UavState> now(m.uavs);
  std::vector<std::size_t> ground_since(m.uavs, 0);  // first frame of the spell on the ground
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto& u = frames[i]["u"];
    const auto where = fmt::format("frames[{}].u", i);
    for (std::size_t k = 0; k < m.uavs; ++k) {
      sim::UavState& s = now[k];
      s = uav_state(u, k, m);
      if (auto broken = sim::state_violation(s, m.plane_change_steps)) {
        check.fail(where, fmt::format("UAV {} {}", k, *broken));
      }
      if (m.no_fly != nullptr) {
        const auto& row =
            (*m.no_fly)[static_cast<std::size_t>(s.pos.y)].get_ref<const std::string&>();
        if (row[static_cast<std::size_t>(s.pos.x)] == '#') {
          check.fail(where, fmt::format("UAV {} is on the no-fly position {}", k, at(s.pos)));
        }
      }
      if (i == 0) {
        if (m.battery && s.battery_left != m.endurance) {
          check.fail(where, fmt::format("UAV {} starts with {} battery steps, not the endurance {}",
                                        k, s.battery_left, m.endurance));
        }
        if (s.airborne && !s.failed) ++counts.sorties;
      } else {
        sim::UavState& b = before[k];
        // A version 2 trace of a mission with launch sites does not record when a UAV is away:
        // such a step is checked as the simulator flies it.
        if (m.away_unrecorded) b.away_left = 1;
        const bool away = b.away_left > 0 || s.away_left > 0;
        if (s.failed || b.flight_left > 0) {
          s.flight_left = b.flight_left - (s.failed ? 0 : 1);
        } else if (!away && grid::adjacent(b.pos, s.pos, m.flights.plane[0])) {
          s.flight_left = m.flights.between(b.pos, s.pos, b.z) - 1;
        }
        // Versions 2 and 3 recorded the climb before a flight home on the plane climbed from until
        // the first move: the plane is not checked across a move away.
        sim::UavState flown = s;
        if (flown.pos != b.pos && (m.away_unrecorded || (m.climb_recorded_at_move && away)))
          flown.z = b.z;
        if (auto broken = sim::step_violation(b, flown, m.plane_change_steps, m.flights)) {
          check.fail(where, fmt::format("UAV {} {} (from frame {})", k, *broken, i - 1));
        }
        if (m.physical()) {
          if (!b.failed && b.airborne && b.battery_left == 0) {
            ++counts.battery_crashes;
            if (counts.first_crash.empty()) {
              counts.first_crash = fmt::format("{}: UAV {} crashed with an empty battery at {}",
                                               where, k, at(s.pos));
            }
          }
          if (!s.failed && (b.airborne || s.airborne)) ++counts.flight_steps;
          if (!s.failed && !b.airborne && s.airborne) ++counts.sorties;
          if (b.airborne && !s.airborne) {
            ground_since[k] = i;
            if (m.battery && s.battery_left < m.reserve && counts.first_low_landing.empty()) {
              counts.first_low_landing = fmt::format(
                  "{}: UAV {} landed with {} battery steps left, less than the reserve of {}",
                  where, k, s.battery_left, m.reserve);
            }
          }
          if (s.battery_left > b.battery_left) {
            // A swap: on the ground at its site (step_violation: a rise is never flown) for the
            // swap time, to a full battery.
            if (s.battery_left != m.endurance) {
              check.fail(where, fmt::format("UAV {} swapped its battery to {} steps, not the "
                                            "endurance {}",
                                            k, s.battery_left, m.endurance));
            }
            const auto ground = i - ground_since[k];
            if (ground < static_cast<std::size_t>(m.swap)) {
              check.fail(where, fmt::format("UAV {} swapped its battery after {} on the ground, "
                                            "less than the swap time of {}",
                                            k, plural(static_cast<int>(ground), "step"),
                                            plural(m.swap, "step")));
            }
          }
        }
      }
      // On the ground only at its own site: take-offs and landings happen there.
      if (m.physical() && !s.airborne) {
        const grid::Cell site = m.sites[static_cast<std::size_t>(m.site_of[k])];
        if (s.pos != site) {
          check.fail(where, fmt::format("UAV {} is on the ground at {}, not at its launch site {}",
                                        k, at(s.pos), at(site)));
        }
      }
    }
    if (m.separation > 0 && m.uavs > 1) {
      // Only airborne UAVs count, as in the simulator: UAVs on the ground at a site have landed.
      for (std::size_t a = 0; a < m.uavs; ++a) {
        if (!now[a].airborne) continue;
        for (std::size_t b = a + 1; b < m.uavs; ++b) {
          if (!now[b].airborne) continue;
          const grid::Cell pa = now[a].pos;
          const grid::Cell pb = now[b].pos;
          // Two UAVs that exchange cells pass through each other (separation 0 for the step).
          const bool exchanged = i > 0 && pa != pb && pa == before[b].pos && pb == before[a].pos;
          const int gap = exchanged ? 0 : grid::chebyshev(pa, pb);
          counts.min_separation = std::min(counts.min_separation.value_or(gap), gap);
          if (gap >= m.separation) continue;
          ++counts.separation_conflicts;
          if (counts.first_conflict.empty()) {
            counts.first_conflict = fmt::format(
                "{}: UAVs {} at {} and {} at {} {}, less than the separation {}", where, a, at(pa),
                b, at(pb),
                exchanged ? "exchanged cells" : fmt::format("are {} apart", plural(gap, "cell")),
                m.separation);
          }
        }
      }
    }
    std::swap(before, now);
  }
  return counts;
}

void check_counts(const TraceChecker& check, const json& result, const TraceMission& m,
                  const TraceCounts& counts) {
  const auto agree = [&](const char* name, long long counted, const std::string& what) {
    const auto where = std::string("result.") + name;
    const auto value =
        check.integer(check.field(result, "result", name), where, 0, std::int64_t{1} << 62);
    if (value != counted) {
      check.fail(where, fmt::format("{}, but the frames hold {}", value, what));
    }
  };
  if (m.physical()) {
    agree("sorties", counts.sorties, plural(static_cast<int>(counts.sorties), "take-off"));
    agree("flight_steps", counts.flight_steps,
          fmt::format("{} UAV-steps airborne", counts.flight_steps));
  }
  if (m.battery) {
    agree("battery_crashes", counts.battery_crashes,
          plural(static_cast<int>(counts.battery_crashes), "crash", "crashes") +
              (counts.first_crash.empty() ? "" : " (the first " + counts.first_crash + ")"));
  }
  if (m.separation > 0 && m.uavs > 1) {
    agree("separation_conflicts", counts.separation_conflicts,
          fmt::format("{} conflicting pair-steps", counts.separation_conflicts) +
              (counts.first_conflict.empty() ? "" : " (the first " + counts.first_conflict + ")"));
    if (counts.min_separation) {
      agree("min_separation", *counts.min_separation,
            fmt::format("a smallest separation of {}", *counts.min_separation));
    } else if (result.contains("min_separation")) {
      // No two UAVs were ever airborne together, so there is no separation to report.
      check.fail("result.min_separation", "present, but no two UAVs are airborne together");
    }
  }
}

}  // namespace hullinspect::io::detail
