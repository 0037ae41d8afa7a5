// The trace format (docs/trace-format.md): a recorded mission passes the reader, its frames rebuild
// the recorded series, and every kind of damage is reported with the file and the field.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include <unistd.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/io/trace_reader.hpp"
#include "hullinspect/io/trace_recorder.hpp"
#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/instance.hpp"
#include "hullinspect/world/mesh_hull.hpp"
#include "hullinspect/world/standoff_surface.hpp"
#include "support/mesh_fixtures.hpp"

namespace hullinspect::io {
namespace {

using nlohmann::json;

// A mission of `algorithm` on `hull`, recorded.
json record_mission(const world::HullMask& hull, const world::MissionParams& params,
                    const std::string& algorithm) {
  const auto instance =
      world::generate_instance(hull, world::CorrosionParams::homogeneous(hull.width(), 0.01, 5), 5);
  auto planner = planners::make_planner(algorithm);
  TraceRecorder recorder(instance, json{{"algorithm", algorithm}});
  planners::MissionOptions options;
  options.observers.push_back(&recorder);
  const auto result = planners::run_mission(hull, instance, params, *planner, options);
  return recorder.finish(result);
}

json record_lawnmower(const world::HullMask& hull, const world::MissionParams& params) {
  return record_mission(hull, params, "lawnmower");
}

// A lawnmower mission of 4 UAVs on the default hull, recorded.
const json& recorded_trace() {
  static const json trace = [] {
    world::MissionParams params;
    params.uavs = 4;
    return record_lawnmower(world::default_hull(), params);
  }();
  return trace;
}

// The message validate_trace gives for the recorded trace after `damage`.
std::string problem_after(const std::function<void(json&)>& damage) {
  json trace = recorded_trace();
  damage(trace);
  try {
    validate_trace(trace, "mission.json");
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "mission.json");
    return e.what();
  }
  return "(accepted)";
}

TEST(TraceReader, AcceptsARecordedMission) {
  EXPECT_NO_THROW(validate_trace(recorded_trace(), "mission.json"));
  EXPECT_EQ(recorded_trace()["format"], kTraceFormat);
  EXPECT_EQ(recorded_trace()["version"], kTraceVersion);
}

TEST(TraceReader, FramesRebuildTheRecordedSeries) {
  // Applying frames 0..t to initial_map gives M(t); its counts are the series of the result.
  const json& trace = recorded_trace();
  const int w = trace["grid"]["width"];
  std::vector<int> map;
  std::vector<int> truth;
  for (const auto& row : trace["initial_map"]) {
    for (char c : row.get<std::string>()) map.push_back(c == '.' ? -1 : c - '0');
  }
  for (const auto& row : trace["truth"]) {
    for (char c : row.get<std::string>()) truth.push_back(c == '.' ? -1 : c - '0');
  }
  ASSERT_EQ(map.size(), truth.size());
  ASSERT_EQ(static_cast<int>(map.size()), w * trace["grid"]["height"].get<int>());
  const auto& frames = trace["frames"];
  for (std::size_t t = 0; t < frames.size(); ++t) {
    const auto& c = frames[t]["c"];
    for (std::size_t j = 0; j < c.size(); j += 2) {
      map[c[j].get<std::size_t>()] = c[j + 1].get<int>();
    }
    int known = 0;
    int inspected = 0;
    for (std::size_t i = 0; i < map.size(); ++i) {
      known += map[i] == 1 || map[i] == 3;
      inspected += map[i] == 3 && truth[i] == 1;
    }
    ASSERT_EQ(known, trace["series"]["known"][t]) << "t = " << t;
    ASSERT_EQ(inspected, trace["series"]["inspected"][t]) << "t = " << t;
  }
  EXPECT_EQ(trace["series"]["known"].back(), trace["result"]["hull_cells"]);
  EXPECT_EQ(trace["result"]["T_m"], frames.size() - 1);
}

TEST(TraceReader, ReadsAFileAndNamesItOnFailure) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("hullinspect-trace-reader-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto good = dir / "good.json";
  std::ofstream(good) << recorded_trace().dump();
  EXPECT_EQ(read_trace(good), recorded_trace());

  const auto broken = dir / "broken.json";
  std::ofstream(broken) << "{\"format\": \"hullinspect-trace\",\n \"version\": 1,\n";
  try {
    read_trace(broken);
    FAIL() << "accepted a truncated file";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              broken.string() +
                  ":3: not a JSON trace: syntax error while parsing object key - "
                  "unexpected end of input; expected string literal");
  }
  try {
    read_trace(dir / "missing.json");
    FAIL() << "read a missing file";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "missing.json").string() + ": cannot open the file");
  }
  std::filesystem::remove_all(dir);
}

TEST(TraceReader, NamesTheDamagedField) {
  EXPECT_EQ(problem_after([](json& t) { t["format"] = "something-else"; }),
            "mission.json: format: expected \"hullinspect-trace\" (not a hullinspect trace?)");
  EXPECT_EQ(problem_after([](json& t) { t["version"] = 5; }),
            "mission.json: version: 5 is not supported (this hullinspect reads versions 1 to 4)");
  EXPECT_EQ(problem_after([](json& t) { t["version"] = 0; }),
            "mission.json: version: 0 is not supported (this hullinspect reads versions 1 to 4)");
  EXPECT_EQ(problem_after([](json& t) { t.erase("frames"); }), "mission.json: frames: missing");
  EXPECT_EQ(problem_after([](json& t) { t["grid"]["width"] = 0; }),
            "mission.json: grid.width: 0 is outside [1, 32768]");
  EXPECT_EQ(problem_after([](json& t) { t["truth"][2] = "..."; }),
            "mission.json: truth[2]: expected 230 characters (the grid width), got 3");
  EXPECT_EQ(problem_after([](json& t) { t["prior"].erase(0); }),
            "mission.json: prior: expected 30 rows (the grid height), got 29");
  EXPECT_EQ(problem_after([](json& t) {
              auto& row = t["initial_map"][10].get_ref<std::string&>();
              row[4] = '7';
            }),
            "mission.json: initial_map[10]: character 4 is '7', expected one of \".0123\"");
  EXPECT_EQ(problem_after([](json& t) {
              auto& row = t["partition"][10].get_ref<std::string&>();
              row[4] = '?';
            }),
            "mission.json: partition[10]: character 4 is '?', expected one of "
            "\".0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ\"");
  EXPECT_EQ(problem_after([](json& t) { t["frames"][3]["t"] = 4; }),
            "mission.json: frames[3].t: 4 is outside [3, 3]");
  EXPECT_EQ(problem_after([](json& t) { t["frames"][3]["u"].erase(0); }),
            "mission.json: frames[3].u: expected 20 numbers (5 per UAV), got 19");
  EXPECT_EQ(problem_after([](json& t) { t["frames"][3]["u"][7] = 3; }),
            "mission.json: frames[3].u[7]: 3 is outside [1, 2]");
  EXPECT_EQ(problem_after([](json& t) { t["frames"][3]["u"][5] = 230; }),
            "mission.json: frames[3].u[5]: 230 is outside [0, 229]");
  EXPECT_EQ(problem_after([](json& t) { t["frames"][0]["c"].push_back(5); }),
            "mission.json: frames[0].c: expected [cell, value] pairs (an even length)");
  EXPECT_EQ(problem_after([](json& t) { t["frames"][0]["c"][0] = 6900; }),
            "mission.json: frames[0].c[0]: 6900 is outside [0, 6899]");
  EXPECT_EQ(problem_after([](json& t) { t["frames"][0]["c"][1] = -1; }),
            "mission.json: frames[0].c[1]: -1 is outside [0, 3]");
  EXPECT_EQ(problem_after([](json& t) {
              t["frames"][2]["p"] = {
                  {"4", {{"mode", "x"}, {"target", nullptr}, {"plan", json::array()}}}};
            }),
            "mission.json: frames[2].p.4: the key must be a UAV index in [0, 3]");
  EXPECT_EQ(problem_after([](json& t) {
              t["frames"][2]["p"] = {
                  {"1", {{"mode", "x"}, {"target", {1, 30}}, {"plan", json::array()}}}};
            }),
            "mission.json: frames[2].p.1.target[1]: 30 is outside [0, 29]");
  EXPECT_EQ(problem_after([](json& t) {
              t["frames"][2]["p"] = {{"1", {{"mode", "x"}, {"target", nullptr}, {"plan", {{1}}}}}};
            }),
            "mission.json: frames[2].p.1.plan[0]: expected [x, y]");
  EXPECT_EQ(problem_after([](json& t) {
              t["frames"][2]["l"] = {{"frontiers", {1, 2, -3}}};
            }),
            "mission.json: frames[2].l.frontiers[2]: -3 is outside [0, 6899]");
  EXPECT_EQ(problem_after([](json& t) {
              t["frames"][2]["l"] = {{"frontiers", {1, 3, 3}}};
            }),
            "mission.json: frames[2].l.frontiers[2]: 3 is not above the previous index 3");
  EXPECT_EQ(problem_after([](json& t) {
              t["frames"][2]["l"] = {{"frontiers", {{"add", {4}}, {"remove", json::array()}}}};
            }),
            "mission.json: frames[2].l.frontiers: changes to a layer whose whole set was not given "
            "before");
  EXPECT_EQ(problem_after([](json& t) {
              t["frames"][1]["l"] = {{"frontiers", {1, 2}}};
              t["frames"][2]["l"] = {{"frontiers", {{"add", {4}}, {"drop", {1}}}}};
            }),
            "mission.json: frames[2].l.frontiers.drop: unknown key (known: add, remove)");
  EXPECT_EQ(problem_after([](json& t) {
              t["frames"][1]["l"] = {{"frontiers", {1, 2}}};
              t["frames"][2]["l"] = {{"frontiers", {{"add", {9, 4}}}}};
            }),
            "mission.json: frames[2].l.frontiers.add[1]: 4 is not above the previous index 9");
  EXPECT_EQ(problem_after([](json& t) {
              t["frames"][2]["l"] = {{"frontiers", 5}};
            }),
            "mission.json: frames[2].l.frontiers: expected the layer's cells (an array) or its "
            "changes {\"add\", \"remove\"}");
  EXPECT_EQ(problem_after([](json& t) { t["series"]["known"].erase(0); }),
            "mission.json: series.known: expected one value per frame (" +
                std::to_string(recorded_trace()["frames"].size()) + "), got " +
                std::to_string(recorded_trace()["frames"].size() - 1));
  EXPECT_EQ(problem_after([](json& t) { t["result"]["T_c"] = 100000; }),
            "mission.json: result.T_c: 100000 is outside [0, " +
                std::to_string(recorded_trace()["frames"].size() - 1) + "]");
  EXPECT_EQ(problem_after([](json& t) { t["result"]["complete"] = 1; }),
            "mission.json: result.complete: expected true or false");
}

TEST(TraceReader, AcceptsOptionalAnnotationsAndLayers) {
  EXPECT_EQ(problem_after([](json& t) {
              t["frames"][2]["p"] = {
                  {"1", {{"mode", "explore"}, {"target", {3, 4}}, {"plan", {{3, 4}, {5, 6}}}}}};
              t["frames"][2]["l"] = {{"frontiers", {1, 2, 3}}, {"claimed", json::array()}};
              t["partition"] = nullptr;
            }),
            "(accepted)");
  // Changes after a whole set, and a version 1 trace (whole sets only).
  EXPECT_EQ(problem_after([](json& t) {
              t["frames"][1]["l"] = {{"frontiers", {1, 2}}};
              t["frames"][2]["l"] = {{"frontiers", {{"add", {4}}, {"remove", {1}}}}};
            }),
            "(accepted)");
  EXPECT_EQ(problem_after([](json& t) { t["version"] = 1; }), "(accepted)");
}

// A `ship_frame` (a hull from a mesh, docs/trace-format.md) on the 230 × 30 default-hull trace:
// 1 m of depth everywhere, normals toward starboard.
void add_ship_frame(json& t) {
  const json depth_row(std::vector<double>(230, 1.0));
  const json normal_row(std::vector<json>(230, json{0, -1, 0}));
  t["ship_frame"] = {{"origin", {-2.5, 0.25}},
                     {"side_plane_y", -4.0},
                     {"side", "starboard"},
                     {"depth", std::vector<json>(30, depth_row)},
                     {"normal", std::vector<json>(30, normal_row)}};
}

TEST(TraceReader, ChecksTheShipFrameOfAMeshHull) {
  EXPECT_EQ(problem_after(add_ship_frame), "(accepted)");
  EXPECT_EQ(problem_after([](json& t) {
              add_ship_frame(t);
              t["ship_frame"]["side"] = "aft";
            }),
            "mission.json: ship_frame.side: expected \"port\", \"starboard\" or \"both\"");
  EXPECT_EQ(problem_after([](json& t) {
              add_ship_frame(t);
              t["ship_frame"].erase("origin");
            }),
            "mission.json: ship_frame.origin: missing");
  EXPECT_EQ(problem_after([](json& t) {
              add_ship_frame(t);
              t["ship_frame"]["depth"].erase(0);
            }),
            "mission.json: ship_frame.depth: expected 30 rows (the grid height), got 29");
  EXPECT_EQ(problem_after([](json& t) {
              add_ship_frame(t);
              t["ship_frame"]["depth"][3][7] = -0.5;
            }),
            "mission.json: ship_frame.depth[3][7]: expected metres >= 0");
  EXPECT_EQ(problem_after([](json& t) {
              add_ship_frame(t);
              t["ship_frame"]["normal"][2][9] = {0, 2, 0};
            }),
            "mission.json: ship_frame.normal[2][9]: expected a unit vector [nx, ny, nz]");
  EXPECT_EQ(problem_after([](json& t) {
              add_ship_frame(t);
              t["ship_frame"]["normal"][2].erase(0);
            }),
            "mission.json: ship_frame.normal[2]: expected 230 values (the grid width), got 229");
}

// An unrolled hull's `ship_frame` (side "both") carries surface points instead of depths.
void add_unrolled_ship_frame(json& t) {
  add_ship_frame(t);
  t["ship_frame"]["side"] = "both";
  t["ship_frame"].erase("depth");
  const json surface_row(std::vector<json>(230, json{1.5, -4.0, 2.0}));
  t["ship_frame"]["surface"] = std::vector<json>(30, surface_row);
}

TEST(TraceReader, ChecksTheSurfaceOfAnUnrolledHull) {
  EXPECT_EQ(problem_after(add_unrolled_ship_frame), "(accepted)");
  EXPECT_EQ(problem_after([](json& t) {
              add_unrolled_ship_frame(t);
              t["ship_frame"].erase("surface");
            }),
            "mission.json: ship_frame.surface: missing");
  EXPECT_EQ(problem_after([](json& t) {
              add_unrolled_ship_frame(t);
              t["ship_frame"]["surface"][4][5] = {1.0, 2.0};
            }),
            "mission.json: ship_frame.surface[4][5]: expected a point [X, Y, Z] in metres");
  EXPECT_EQ(problem_after([](json& t) {
              add_unrolled_ship_frame(t);
              t["ship_frame"]["surface"][4][5] = {1.0, 2.0, 1e9};
            }),
            "mission.json: ship_frame.surface[4][5]: expected metres in [-100000, 100000]");
}

// A lawnmower mission of 3 UAVs on the unrolled Wigley hull, recorded: its neighbour flights
// around the stem take several steps (docs/model.md "Neighbour flights").
world::HullMask unrolled_wigley() {
  world::MeshImportOptions o;
  o.side = world::HullSide::both;
  o.cell_size = 1.0;
  return world::import_mesh_file(testing::wigley_stl(testing::WigleyHull{}), o).hull;
}

world::MissionParams unrolled_params() {
  world::MissionParams params;
  params.uavs = 3;
  params.cell_size_m = 1.0;
  return params;
}

const json& unrolled_trace() {
  static const json trace = record_lawnmower(unrolled_wigley(), unrolled_params());
  return trace;
}

TEST(TraceReader, AUavStaysPutWhileItFliesToADistantNeighbour) {
  json trace = unrolled_trace();
  EXPECT_NO_THROW(validate_trace(trace, "mission.json"));
  // The first move of a flight longer than one step.
  const grid::FlightSteps flights = world::neighbour_flights(unrolled_wigley(), unrolled_params());
  auto& frames = trace["frames"];
  const auto x = [&](std::size_t i, std::size_t k) { return frames[i]["u"][5 * k].get<int>(); };
  const auto y = [&](std::size_t i, std::size_t k) { return frames[i]["u"][5 * k + 1].get<int>(); };
  const std::size_t uavs = frames[0]["u"].size() / 5;
  std::size_t at = 0, uav = 0;
  for (std::size_t i = 1; i + 1 < frames.size() && at == 0; ++i) {
    for (std::size_t k = 0; k < uavs && at == 0; ++k) {
      const bool moved = std::abs(x(i, k) - x(i - 1, k)) + std::abs(y(i, k) - y(i - 1, k)) == 1;
      const int z = frames[i - 1]["u"][5 * k + 2].get<int>();
      if (moved && flights.between({x(i - 1, k), y(i - 1, k)}, {x(i, k), y(i, k)}, z) > 1) {
        at = i;
        uav = k;
      }
    }
  }
  ASSERT_GT(at, 0u) << "no long flight in the mission: the test proves nothing";
  // Moving on one frame early (back where it came from) breaks the flight.
  frames[at + 1]["u"][5 * uav] = x(at - 1, uav);
  frames[at + 1]["u"][5 * uav + 1] = y(at - 1, uav);
  try {
    validate_trace(trace, "mission.json");
    ADD_FAILURE() << "accepted a UAV that moved mid-flight";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr(fmt::format(
                              "frames[{}].u: UAV {} moved or changed plane with", at + 1, uav)));
  }
}

// A hull closed at its seam (the Wigley stern with --include transom): a recorded move across the
// seam is one neighbour flight, which the reader replays from `ship_frame.seam`.
TEST(TraceReader, AMoveAcrossTheSeamIsANeighbourFlight) {
  world::MeshImportOptions o;
  o.side = world::HullSide::both;
  o.include_transom = true;
  o.cell_size = 1.0;
  const world::HullMask hull =
      world::import_mesh_file(testing::wigley_stl(testing::WigleyHull{}), o).hull;
  world::MissionParams params = unrolled_params();
  params.uavs = 4;
  const int w = hull.width();
  // The first registered planner whose UAVs cross the seam.
  for (const auto& info : planners::planner_registry()) {
    json trace = record_mission(hull, params, info.name);
    ASSERT_TRUE(trace["ship_frame"].value("seam", false)) << info.name;
    const auto& frames = trace["frames"];
    const std::size_t uavs = frames[0]["u"].size() / 5;
    std::size_t at = 0;
    for (std::size_t i = 1; i < frames.size() && at == 0; ++i) {
      for (std::size_t k = 0; k < uavs; ++k) {
        const int dx = frames[i]["u"][5 * k].get<int>() - frames[i - 1]["u"][5 * k].get<int>();
        if (std::abs(dx) == w - 1) at = i;
      }
    }
    if (at == 0) continue;
    EXPECT_NO_THROW(validate_trace(trace, "mission.json")) << info.name;
    // Without the link the same move is a jump across the grid.
    trace["ship_frame"].erase("seam");
    try {
      validate_trace(trace, "mission.json");
      ADD_FAILURE() << "accepted a move across an unlinked seam";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr(fmt::format("moved {} cells in one step", w - 1)));
    }
    return;
  }
  FAIL() << "no planner crossed the seam: the test proves nothing";
}

}  // namespace
}  // namespace hullinspect::io
