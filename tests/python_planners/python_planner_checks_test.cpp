// Python planners (hullinspect.Planner subclasses, registered through python/planner_bridge.cpp)
// under the same checks as the built-in planners: the shared mission checker and the
// truth-blindness check. Python runs embedded in this test program; the planner is plain Python
// with numpy, registered exactly as hullinspect.register_planner registers it. Release builds
// only (cmake/Dependencies.cmake: no Python in sanitizer builds).

#include <gtest/gtest.h>
#include <pybind11/embed.h>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/scenario.hpp"
#include "planner_bridge.hpp"
#include "support/mission_checker.hpp"
#include "support/truth_blindness.hpp"

namespace hullinspect {
namespace {

namespace py = pybind11;

// The planner of examples/03_python_planner.py, without the package around it.
constexpr const char* kPlanners = R"(
import numpy as np

class NearestOpen:
    """close-up sweep to the nearest open cell"""

    def start(self, context):
        self.width = context.hull.shape[1]

    def decide(self, view):
        open_y, open_x = np.nonzero((view.map == 0) | (view.map == 2))
        actions = []
        for (x, y, z, in_transit, failed) in view.uavs:
            if in_transit or failed or len(open_x) == 0:
                actions.append("hover")
            elif z == 2:
                actions.append("change")
            else:
                i = int(np.argmin(np.abs(open_x - x) + np.abs(open_y - y)))
                tx, ty = int(open_x[i]), int(open_y[i])
                actions.append("E" if tx > x else "W" if tx < x else
                               "N" if ty > y else "S" if ty < y else "hover")
        return actions
)";

class PythonPlannerChecks : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One interpreter for the program (never finalised: numpy cannot be re-initialised). The
    // missions run with the GIL released, as in the module; the bridge takes it for Python.
    static py::scoped_interpreter interpreter;
    py::dict scope;
    py::exec(kPlanners, scope);
    python::register_python_planner("py-nearest-open", scope["NearestOpen"],
                                    "close-up sweep to the nearest open cell");
    static py::gil_scoped_release release;
  }
};

TEST_F(PythonPlannerChecks, MissionsPassTheSharedMissionChecker) {
  for (const char* scenario : {"perfect", "imperfect"}) {
    for (int uavs : {1, 3}) {
      planners::MissionSpec spec;
      spec.algorithm = "py-nearest-open";
      spec.seed = 4;
      spec.params.uavs = uavs;
      spec.corrosion = world::scenario(scenario).corrosion(world::default_hull().width());
      spec.failures.at.push_back({uavs - 1, 150});  // the rules for failed UAVs too
      testing::MissionChecker checker;
      planners::MissionOptions options;
      options.observers = {&checker};
      const auto r = planners::run_mission(spec, world::default_hull(), options);
      SCOPED_TRACE(::testing::Message() << scenario << " n = " << uavs);
      EXPECT_TRUE(checker.ok());
      EXPECT_GT(checker.steps_checked(), 150);
      EXPECT_EQ(r.failed_uavs, 1);
      EXPECT_EQ(r.complete, uavs > 1);  // the others finish the failed UAV's work
    }
  }
}

TEST_F(PythonPlannerChecks, DecisionsDependOnlyOnWhatWasSensed) {
  world::MissionParams params;
  params.uavs = 4;
  testing::TruthBlindnessReport report;
  EXPECT_TRUE(testing::planner_is_truth_blind("py-nearest-open", {}, params, 5, &report));
  EXPECT_GE(report.first_differing_reading, 1);  // the two missions did diverge
}

}  // namespace
}  // namespace hullinspect
