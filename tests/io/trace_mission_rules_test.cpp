// A trace of a mission with launch sites and batteries records it whole (docs/trace-format.md,
// "Rules"): every registered planner's trace keeps every rule when read back, and a trace broken
// by hand in one rule is refused with one line naming the frame and the rule.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/io/trace_reader.hpp"
#include "hullinspect/io/trace_rules.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/hull.hpp"
#include "support/trace_rules_checker.hpp"

namespace hullinspect::io {
namespace {

using nlohmann::json;

// Batteries of 400 s (swaps of 30 s) and two launch sites 20 cells apart in the middle of the
// default hull's bottom edge.
planners::MissionSpec battery_mission(const std::string& algorithm, int uavs, int separation) {
  const auto& hull = world::default_hull();
  planners::MissionSpec spec;
  spec.algorithm = algorithm;
  spec.seed = 2;
  spec.params.uavs = uavs;
  spec.params.launch_sites = {{hull.width() / 2 - 10, 0}, {hull.width() / 2 + 10, 0}};
  spec.params.endurance_s = 400;
  spec.params.swap_time_s = 30;
  spec.params.separation = separation;
  return spec;
}

class EveryPlannerTrace : public ::testing::TestWithParam<std::string> {};

// Four UAVs, two to a site: they swap batteries, and the trace says so step by step.
TEST_P(EveryPlannerTrace, KeepsEveryRuleWithBatteriesAndTwoSites) {
  const json trace =
      testing::recorded_trace(battery_mission(GetParam(), 4, 0), world::default_hull());
  EXPECT_TRUE(testing::trace_keeps_the_rules(trace));
  EXPECT_EQ(trace["version"], kTraceVersion);
  EXPECT_EQ(trace["uav_fields"].size(), kPhysicalUavFields.size());
  EXPECT_EQ(trace["launch"]["sites"].size(), 2U);
  EXPECT_EQ(trace["battery"]["swap_steps"], 30);
  EXPECT_TRUE(trace["result"]["complete"].get<bool>());
  EXPECT_GT(trace["result"]["sorties"].get<int>(), 4) << "no UAV swapped its battery";
  EXPECT_EQ(trace["result"]["battery_crashes"], 0);
}

// One UAV to a site, at a separation of 2: no two UAVs closer than 2 at any step.
TEST_P(EveryPlannerTrace, KeepsTheSeparationWithASiteEach) {
  const json trace =
      testing::recorded_trace(battery_mission(GetParam(), 2, 2), world::default_hull());
  EXPECT_TRUE(testing::trace_keeps_the_rules(trace));
  EXPECT_EQ(trace["separation"], 2);
  EXPECT_EQ(trace["result"]["separation_conflicts"], 0);
}

std::vector<std::string> planner_names() {
  std::vector<std::string> names;
  for (const auto& info : planners::planner_registry()) names.push_back(info.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryPlannerTrace, ::testing::ValuesIn(planner_names()),
                         [](const auto& param_info) {
                           std::string name = param_info.param;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

// A lawnmower mission of two UAVs, a site each, separation 1, batteries that force swaps.
const json& lawnmower_trace() {
  static const json trace =
      testing::recorded_trace(battery_mission("lawnmower", 2, 1), world::default_hull());
  return trace;
}

constexpr std::size_t kFields = kPhysicalUavFields.size();
constexpr std::size_t kAirborne = 5;
constexpr std::size_t kBattery = 6;

int value(const json& trace, std::size_t frame, std::size_t k, std::size_t field) {
  return trace["frames"][frame]["u"][kFields * k + field].get<int>();
}

// The message of the check after `damage`: validate_trace's, or check_trace_safety's when
// `safety` (validate_trace must then accept the damaged trace).
std::string problem_after(const std::function<void(json&)>& damage, bool safety = false) {
  json trace = lawnmower_trace();
  damage(trace);
  try {
    validate_trace(trace, "m.json");
    if (!safety) return "(accepted)";
    check_trace_safety(trace, "m.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

// The first frame after `from` where UAV k's `field` satisfies `want`.
std::size_t first_frame(const json& trace, std::size_t from, std::size_t k,
                        const std::function<bool(std::size_t)>& want) {
  for (std::size_t i = from; i < trace["frames"].size(); ++i) {
    if (want(i)) return i;
  }
  ADD_FAILURE() << "no such frame for UAV " << k;
  return 0;
}

TEST(TraceMissionRules, TheRecordedTraceKeepsThemAll) {
  EXPECT_TRUE(testing::trace_keeps_the_rules(lawnmower_trace()));
  EXPECT_GT(lawnmower_trace()["result"]["sorties"].get<int>(), 2);
}

// Two UAVs on one site at D = 2 with a time limit before the second takes off: the separation
// is counted (no conflict) but never measured, and the trace still reads and keeps the rules.
TEST(TraceMissionRules, NoTwoUavsAirborneTogetherHasNoSmallestSeparation) {
  auto spec = battery_mission("lawnmower", 2, 2);
  spec.params.launch_sites.resize(1);
  spec.params.time_limit = 2;
  const json trace = testing::recorded_trace(spec, world::default_hull());
  EXPECT_EQ(trace["result"]["separation_conflicts"], 0);
  EXPECT_FALSE(trace["result"].contains("min_separation"));
  EXPECT_TRUE(testing::trace_keeps_the_rules(trace));
}

TEST(TraceMissionRules, ABatteryBelowZeroWhileAirborne) {
  const json& t = lawnmower_trace();
  const auto i =
      first_frame(t, 1, 0, [&](std::size_t f) { return value(t, f, 0, kAirborne) == 1; });
  EXPECT_EQ(problem_after([&](json& d) { d["frames"][i]["u"][kBattery] = -1; }),
            fmt::format("m.json: frames[{}].u[6]: -1 is outside [0, 400]", i));
}

TEST(TraceMissionRules, AnEmptyBatteryThatFliesOn) {
  // UAV 0's battery at 0 in a frame where it flies on: it must have crashed instead.
  const json& t = lawnmower_trace();
  const auto i = first_frame(t, 1, 0, [&](std::size_t f) {
    return value(t, f, 0, kAirborne) == 1 && value(t, f + 1, 0, kAirborne) == 1;
  });
  const int before = value(t, i - 1, 0, kBattery);
  EXPECT_EQ(problem_after([&](json& d) { d["frames"][i]["u"][kBattery] = 0; }),
            fmt::format("m.json: frames[{}].u: UAV 0 flew a step and its battery went from {} "
                        "to 0 steps (from frame {})",
                        i, before, i - 1));
}

TEST(TraceMissionRules, ATakeOffOffItsSite) {
  // UAV 0 waits on the ground at its site until it takes off; moved one cell east, it is on the
  // ground off its site from frame 0 on.
  const json& t = lawnmower_trace();
  const auto takeoff =
      first_frame(t, 0, 0, [&](std::size_t f) { return value(t, f, 0, kAirborne) == 1; });
  ASSERT_GT(takeoff, 0U);
  const int x = value(t, 0, 0, 0);
  const int y = value(t, 0, 0, 1);
  EXPECT_EQ(problem_after([&](json& d) {
              for (std::size_t f = 0; f < takeoff; ++f) d["frames"][f]["u"][0] = x + 1;
            }),
            fmt::format("m.json: frames[0].u: UAV 0 is on the ground at ({}, {}), not at its "
                        "launch site ({}, {})",
                        x + 1, y, x, y));
}

TEST(TraceMissionRules, ALandingOnTheHull) {
  // UAV 0 on the ground for one frame in the middle of a sortie, on the hull. Just back from its
  // site (away in the frame before) it is on the ground off its site; at work for two frames, it
  // also landed without flying home.
  const json& t = lawnmower_trace();
  const auto i = first_frame(t, 1, 0, [&](std::size_t f) {
    return value(t, f, 0, kAirborne) == 1 && value(t, f, 0, 7) == 0;
  });
  EXPECT_EQ(
      problem_after([&](json& d) { d["frames"][i]["u"][kAirborne] = 0; }),
      fmt::format("m.json: frames[{}].u: UAV 0 is on the ground at ({}, {}), not at its "
                  "launch site ({}, {})",
                  i, value(t, i, 0, 0), value(t, i, 0, 1), value(t, 0, 0, 0), value(t, 0, 0, 1)));
  const auto j = i + 2;
  ASSERT_EQ(value(t, j - 1, 0, 7), 0);
  EXPECT_EQ(problem_after([&](json& d) { d["frames"][j]["u"][kAirborne] = 0; }),
            fmt::format("m.json: frames[{}].u: UAV 0 landed away from a launch site (from frame "
                        "{})",
                        j, j - 1));
}

TEST(TraceMissionRules, ASwapShorterThanTheSwapTime) {
  // UAV k's first new battery, one frame early: 29 steps on the ground instead of 30.
  const json& t = lawnmower_trace();
  std::size_t k = 0;
  std::size_t i = 0;
  for (; k < 2 && i == 0; ++k) {
    for (std::size_t f = 1; f < t["frames"].size() && i == 0; ++f) {
      if (value(t, f, k, kBattery) > value(t, f - 1, k, kBattery)) i = f;
    }
  }
  --k;
  ASSERT_GT(i, 0U) << "no swap";
  EXPECT_EQ(problem_after([&](json& d) { d["frames"][i - 1]["u"][kFields * k + kBattery] = 400; }),
            fmt::format("m.json: frames[{}].u: UAV {} swapped its battery after 29 steps on the "
                        "ground, less than the swap time of 30 steps",
                        i - 1, k));
  // A new battery that is not full.
  EXPECT_EQ(problem_after([&](json& d) { d["frames"][i]["u"][kFields * k + kBattery] = 399; }),
            fmt::format("m.json: frames[{}].u: UAV {} swapped its battery to 399 steps, not the "
                        "endurance 400",
                        i, k));
}

TEST(TraceMissionRules, TwoUavsCloserThanTheSeparation) {
  // The trace's own separation 1 is kept; at a separation larger than the smallest flown, the
  // frames hold conflicts the result does not count, and the safety check names the first.
  const json& t = lawnmower_trace();
  const int smallest = t["result"]["min_separation"].get<int>();
  ASSERT_EQ(t["result"]["separation_conflicts"], 0);
  const auto raise = [&](json& d) { d["separation"] = smallest + 1; };
  const std::string counted = problem_after(raise);
  EXPECT_EQ(counted.rfind("m.json: result.separation_conflicts: 0, but the frames hold ", 0), 0U)
      << counted;
  EXPECT_NE(counted.find(fmt::format("are {} apart, less than the separation {})",
                                     smallest == 1 ? "1 cell" : fmt::format("{} cells", smallest),
                                     smallest + 1)),
            std::string::npos)
      << counted;
  // Counted in the result too, the trace is valid but unsafe.
  const std::string unsafe = problem_after(
      [&](json& d) {
        raise(d);
        json copy = d;
        copy["result"]["separation_conflicts"] = 0;
        try {
          validate_trace(copy, "m.json");
        } catch (const InputError& e) {
          const std::string m = e.what();
          const auto from = m.find("hold ") + 5;
          d["result"]["separation_conflicts"] = std::stoll(m.substr(from));
        }
      },
      true);
  EXPECT_EQ(unsafe.rfind("m.json: frames[", 0), 0U) << unsafe;
  EXPECT_NE(unsafe.find(fmt::format("less than the separation {}", smallest + 1)),
            std::string::npos)
      << unsafe;
}

TEST(TraceMissionRules, ALandingBelowTheReserve) {
  // With a reserve above what UAV k had left at a landing, the landing breaks it.
  const json& t = lawnmower_trace();
  int least = 400;
  for (std::size_t f = 1; f < t["frames"].size(); ++f) {
    for (std::size_t k = 0; k < 2; ++k) {
      if (value(t, f - 1, k, kAirborne) == 1 && value(t, f, k, kAirborne) == 0)
        least = std::min(least, value(t, f, k, kBattery));
    }
  }
  ASSERT_GE(least, t["battery"]["reserve_steps"].get<int>());
  const std::string message =
      problem_after([&](json& d) { d["battery"]["reserve_steps"] = least + 1; }, true);
  EXPECT_NE(message.find(fmt::format("landed with {} battery steps left, less than the reserve "
                                     "of {}",
                                     least, least + 1)),
            std::string::npos)
      << message;
}

constexpr std::size_t kZ = 2;
constexpr std::size_t kAway = 7;

// Where UAVs at work on plane 1 begin a flight home (for a swap, or at the end of the mission):
// per such flight, the UAV and its last frame at the cell where it was when it became away.
std::vector<std::pair<std::size_t, std::size_t>> climbs_home(const json& t) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  const std::size_t uavs = t["frames"][0]["u"].size() / kFields;
  const std::size_t frames = t["frames"].size();
  for (std::size_t k = 0; k < uavs; ++k) {
    for (std::size_t f = 1; f < frames; ++f) {
      if (value(t, f - 1, k, kAway) != 0 || value(t, f, k, kAway) == 0 ||
          value(t, f, k, kAirborne) == 0 ||
          (value(t, f - 1, k, kZ) != 1 && value(t, f, k, kZ) != 1))
        continue;
      std::size_t g = f;
      while (g + 1 < frames && value(t, g + 1, k, 0) == value(t, f, k, 0) &&
             value(t, g + 1, k, 1) == value(t, f, k, 1))
        ++g;
      out.emplace_back(k, g);
    }
  }
  return out;
}

// A UAV at work on plane 1 that flies home (sent home for a swap, or when the hull is known)
// climbs to plane 2 at the cell where it is and only then flies on: in its last frame at that
// cell it is on plane 2.
TEST(TraceMissionRules, AFlightHomeClimbsWhereTheUavIs) {
  std::size_t flights = 0;
  for (const char* algorithm : {"lawnmower", "part-tsp", "coop-frontier", "sweep-inspect"}) {
    const json t = testing::recorded_trace(battery_mission(algorithm, 4, 0), world::default_hull());
    EXPECT_TRUE(testing::trace_keeps_the_rules(t)) << algorithm;
    for (const auto& [k, g] : climbs_home(t)) {
      ++flights;
      EXPECT_EQ(value(t, g, k, kZ), 2) << algorithm << ": UAV " << k << ", frame " << g;
    }
  }
  EXPECT_GT(flights, 0U) << "no UAV flew home from plane 1";
}

// The climb recorded one cell late, on the way: the UAV moved and changed plane in one step.
TEST(TraceMissionRules, AClimbHomeOnTheWay) {
  const json t = testing::recorded_trace(battery_mission("lawnmower", 4, 0), world::default_hull());
  const auto climbs = climbs_home(t);
  ASSERT_FALSE(climbs.empty()) << "no UAV flew home from plane 1";
  const auto [k, g] = climbs.front();
  ASSERT_LT(g + 1, t["frames"].size());
  json broken = t;
  broken["frames"][g]["u"][kFields * k + kZ] = 1;
  std::string message = "(accepted)";
  try {
    validate_trace(broken, "m.json");
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_EQ(message, fmt::format("m.json: frames[{}].u: UAV {} moved from ({}, {}) on plane 1 to "
                                 "({}, {}) on plane 2 in one step (from frame {})",
                                 g + 1, k, value(t, g, k, 0), value(t, g, k, 1),
                                 value(t, g + 1, k, 0), value(t, g + 1, k, 1), g));
  // Version 3 recorded the climb that way: such a trace is still read.
  broken["version"] = 3;
  EXPECT_NO_THROW(validate_trace(broken, "m.json"));
}

TEST(TraceMissionRules, CountsTheResultMustAgreeWith) {
  EXPECT_EQ(problem_after([](json& d) { d["result"]["battery_crashes"] = 1; }),
            "m.json: result.battery_crashes: 1, but the frames hold 0 crashes");
  const int sorties = lawnmower_trace()["result"]["sorties"].get<int>();
  EXPECT_EQ(problem_after([&](json& d) { d["result"]["sorties"] = sorties + 1; }),
            fmt::format("m.json: result.sorties: {}, but the frames hold {} take-offs", sorties + 1,
                        sorties));
}

TEST(TraceMissionRules, ACompleteMissionEndsOnTheGround) {
  // Without its last frame (a landing), the mission claims to be complete with a UAV airborne.
  const json& t = lawnmower_trace();
  const auto last = t["frames"].size() - 1;
  int airborne = -1;
  int last_step_flown = 0;
  for (std::size_t k = 0; k < 2; ++k) {
    if (value(t, last - 1, k, kAirborne) == 1 && airborne < 0) airborne = static_cast<int>(k);
    last_step_flown += value(t, last - 1, k, kAirborne) | value(t, last, k, kAirborne);
  }
  ASSERT_GE(airborne, 0);
  EXPECT_EQ(
      problem_after([&](json& d) {
        d["frames"].erase(last);
        d["series"]["inspected"].erase(last);
        d["series"]["known"].erase(last);
        d["result"]["steps"] = last - 1;
        d["result"]["T_m"] = last - 1;
        d["result"]["flight_steps"] = d["result"]["flight_steps"].get<int>() - last_step_flown;
      }),
      fmt::format("m.json: result.complete: true, but UAV {} has not landed in the last frame",
                  airborne));
}

TEST(TraceMissionRules, TheLayoutFollowsTheVersion) {
  // Version 2 had the paper's five values per UAV only; version 3 of a mission with launch sites
  // has eight.
  EXPECT_EQ(problem_after([](json& d) { d["version"] = 2; }),
            "m.json: uav_fields: expected [\"x\",\"y\",\"z\",\"transit_left\",\"active\"]");
  EXPECT_EQ(problem_after([](json& d) {
              d["uav_fields"] = {"x", "y", "z", "transit_left", "active"};
            }),
            "m.json: uav_fields: expected "
            "[\"x\",\"y\",\"z\",\"transit_left\",\"active\",\"airborne\",\"battery_left\","
            "\"away_left\"] (a mission with launch sites)");
  EXPECT_EQ(problem_after([](json& d) { d.erase("launch"); }),
            "m.json: uav_fields: expected [\"x\",\"y\",\"z\",\"transit_left\",\"active\"]");
}

}  // namespace
}  // namespace hullinspect::io

namespace hullinspect::io {
namespace {

TEST(TraceMissionRules, OlderVersionsAreStillRead) {
  // A version 2 trace of the same mission: five values per UAV, no launch or battery fields, the
  // sites only among the parameters. It is read, its away steps checked loosely.
  json old = lawnmower_trace();
  old["version"] = 2;
  old.erase("launch");
  old.erase("battery");
  old.erase("separation");
  old["uav_fields"] = {"x", "y", "z", "transit_left", "active"};
  old["parameters"]["launch"] = {{"sites", {{105, 0}, {125, 0}}}};
  for (auto& f : old["frames"]) {
    json u = json::array();
    for (std::size_t j = 0; j < f["u"].size(); ++j) {
      if (j % kFields < kPaperUavFields.size()) u.push_back(f["u"][j]);
    }
    f["u"] = std::move(u);
  }
  EXPECT_NO_THROW(validate_trace(old, "old.json"));
  EXPECT_NO_THROW(check_trace_safety(old, "old.json"));
  // A trace of the paper's model reads as version 1 and 2 too (version 1 may lack uav_fields).
  planners::MissionSpec paper;
  paper.params.uavs = 2;
  json v1 = testing::recorded_trace(paper, world::default_hull());
  EXPECT_EQ(v1["uav_fields"].size(), kPaperUavFields.size());
  EXPECT_FALSE(v1.contains("launch") || v1.contains("battery") || v1.contains("separation"));
  v1["version"] = 2;
  EXPECT_NO_THROW(validate_trace(v1, "v2.json"));
  v1["version"] = 1;
  v1.erase("uav_fields");
  EXPECT_NO_THROW(validate_trace(v1, "v1.json"));
}

}  // namespace
}  // namespace hullinspect::io
