// Simplification keeps coverage (docs/export.md "Simplification"): on the DTC hull, for every
// registered planner, the simplified waypoints stay within the tolerance of the planned path and
// their footprints contain every cell the planned path's footprints contained — checked against
// the model's s_z × s_z footprints at every trace frame, not only against the library's checker.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "hullinspect/io/export.hpp"
#include "hullinspect/io/simplify.hpp"
#include "hullinspect/io/trace_reader.hpp"
#include "hullinspect/planners/planner.hpp"
#include "support/cli_runner.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;
using Seen = std::vector<std::vector<char>>;

// The model's footprints at every frame of the trace (SPEC §3): the s_z × s_z cells around each
// active UAV that is on a plane.
Seen model_footprints(const nlohmann::json& trace, const io::ExportPlan& plan) {
  Seen seen(static_cast<std::size_t>(plan.height),
            std::vector<char>(static_cast<std::size_t>(plan.width), 0));
  const int s[3] = {0, trace["footprint"][0].get<int>(), trace["footprint"][1].get<int>()};
  for (const auto& uav : io::trace_states(trace)) {
    for (const auto& st : uav) {
      if (!st.active || st.in_transit) continue;
      const int r = (s[st.z] - 1) / 2;
      for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
          const int x = st.pos.x + dx, y = st.pos.y + dy;
          if (x >= 0 && y >= 0 && x < plan.width && y < plan.height) {
            seen[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] = 1;
          }
        }
      }
    }
  }
  return seen;
}

// The distance from p to the polyline of `path` (ship frame, metres).
double distance_to_path(const io::ShipPose& p, const std::vector<io::ExportWaypoint>& path) {
  double best = std::hypot(p.x - path[0].pose.x, p.y - path[0].pose.y, p.z - path[0].pose.z);
  for (std::size_t i = 1; i < path.size(); ++i) {
    const auto& a = path[i - 1].pose;
    const auto& b = path[i].pose;
    const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
    const double len2 = dx * dx + dy * dy + dz * dz;
    const double t =
        len2 > 0
            ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy + (p.z - a.z) * dz) / len2, 0.0, 1.0)
            : 0.0;
    best = std::min(best, std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy, p.z - a.z - t * dz));
  }
  return best;
}

class SimplifyOnDtc : public ::testing::TestWithParam<std::string> {};

TEST_P(SimplifyOnDtc, KeepsCoverageWithinTheTolerance) {
  const auto dir = make_temp_dir("simplify-" + GetParam());
  const std::string trace_path = dir + "/trace.json";
  const auto r =
      run_cli({"plan", "--hull", "dtc", "-a", GetParam(), "-n", "4", "--trace", trace_path});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto trace = io::read_trace(trace_path);
  const auto plan = io::export_plan(trace);
  const auto model = model_footprints(trace, plan);
  constexpr double kTolerance = 0.1;
  Seen before(model.size(), std::vector<char>(model[0].size(), 0));
  Seen after = before;
  std::size_t original_count = 0, simplified_count = 0;
  for (auto sortie : io::plan_sorties(plan, {})) {
    const auto original = sortie.waypoints;
    io::mark_seen(plan, original, before);
    io::simplify_sortie(plan, sortie, kTolerance);
    io::mark_seen(plan, sortie.waypoints, after);
    original_count += original.size();
    simplified_count += sortie.waypoints.size();
    for (const auto& w : sortie.waypoints) {
      EXPECT_LE(distance_to_path(w.pose, original), kTolerance + 1e-9) << "UAV " << sortie.uav;
    }
  }
  // The checker sees exactly the model's footprints along the planned path...
  EXPECT_EQ(before, model);
  // ...and the simplified path sees every one of those cells.
  for (int y = 0; y < plan.height; ++y) {
    for (int x = 0; x < plan.width; ++x) {
      const auto ys = static_cast<std::size_t>(y), xs = static_cast<std::size_t>(x);
      if (model[ys][xs]) {
        EXPECT_TRUE(after[ys][xs]) << GetParam() << ": cell " << x << "," << y;
      }
    }
  }
  EXPECT_LT(simplified_count, original_count) << "nothing was simplified: the test proves nothing";
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(EveryPlanner, SimplifyOnDtc,
                         ::testing::ValuesIn(planners::planners().names()),
                         [](const auto& param_info) {
                           std::string name = param_info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(SimplifyChecker, NamesTheFirstCellAShortcutLoses) {
  const auto dir = make_temp_dir("simplify-checker");
  const std::string trace_path = dir + "/trace.json";
  ASSERT_EQ(run_cli({"plan", "-n", "1", "--seed", "1", "--trace", trace_path}).status, 0);
  const auto plan = io::export_plan(io::read_trace(trace_path));
  const auto& original = plan.uavs[0];
  ASSERT_GT(original.size(), 4u);
  // Cutting out the path's second half loses the cells only it saw.
  const std::vector<io::ExportWaypoint> cut(
      original.begin(), original.begin() + static_cast<long>(original.size() / 2));
  const auto lost = io::first_cell_lost(plan, original, cut);
  ASSERT_TRUE(lost.has_value());
  Seen seen_cut(static_cast<std::size_t>(plan.height),
                std::vector<char>(static_cast<std::size_t>(plan.width), 0));
  io::mark_seen(plan, cut, seen_cut);
  EXPECT_FALSE(seen_cut[static_cast<std::size_t>(lost->y)][static_cast<std::size_t>(lost->x)]);
  EXPECT_FALSE(io::first_cell_lost(plan, original, original).has_value());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hullinspect::testing
