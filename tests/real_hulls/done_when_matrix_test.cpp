// Real hulls end to end as one test matrix (docs/hulls.md): the default hull, the DTC and a Wigley
// hull each run every registered planner to completion — in process under the shared
// MissionChecker, from the CLI (`hullinspect run`, its trace checked against the no-fly zones) and
// from a YAML config (`hullinspect experiment`) — with and without no-fly zones, and with the
// generated or with the user's own prior and truth maps. The CLI must reproduce the in-process
// mission exactly (same T_c, T_m and steps).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "hullinspect/experiment/csv.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/mesh_hull.hpp"
#include "hullinspect/world/no_fly.hpp"
#include "hullinspect/world/scenario.hpp"
#include "support/cli_runner.hpp"
#include "support/mesh_fixtures.hpp"
#include "support/mission_checker.hpp"

namespace hullinspect::testing {
namespace {

using nlohmann::json;

// The DTC at 2 m cells (187 × 17): its 72 missions take 2.6 times less than at its own 0.5 m
// (746 × 68 cells), which would make this the slowest test of the suite under ASan.
constexpr double kDtcCellM = 2.0;
constexpr int kUavs = 4;
constexpr int kS2 = 7;
constexpr int kSeed = 3;

/// A hull of the matrix and how the CLI and a config name it.
struct MatrixHull {
  world::HullMask hull;
  std::vector<std::string> cli;  // the --hull arguments of `run`
  std::string yaml;              // the config's `hull:` value
};

std::string number_text(double v) {
  return fmt::format("{}", v);
}

/// The hull named `name` ("default", "wigley", "dtc"), imported once; nullopt with `why` when the
/// DTC is not installed.
const MatrixHull* matrix_hull(const std::string& name, std::string& why) {
  static std::map<std::string, MatrixHull> hulls;
  if (auto it = hulls.find(name); it != hulls.end()) return &it->second;
  if (name == "default") {
    return &hulls.emplace(name, MatrixHull{world::default_hull(), {}, "default"}).first->second;
  }
  if (name == "wigley") {
    const auto stl = wigley_stl(WigleyHull{});  // 100 m × 10 m × 8 m
    world::MeshImportOptions o;
    o.cell_size = 1.0;  // 100 × 8 cells
    return &hulls
                .emplace(name,
                         MatrixHull{world::import_mesh_file(stl, o).hull,
                                    {"--hull", stl.string(), "--cell-size", "1"},
                                    fmt::format("{{mesh: '{}', cell-size: 1}}", stl.string())})
                .first->second;
  }
  const auto dtc = installed_dtc(why);
  if (!dtc) return nullptr;
  world::MeshImportOptions o = world::dtc_options();
  o.cell_size = kDtcCellM;
  return &hulls
              .emplace(name, MatrixHull{world::import_named_mesh_hull("dtc", o).hull,
                                        {"--hull", "dtc", "--cell-size", number_text(kDtcCellM)},
                                        fmt::format("{{mesh: dtc, cell-size: {}}}", kDtcCellM)})
              .first->second;
}

/// Every registered planner, in registration order; never silently fewer than the paper's four.
std::vector<std::string> every_planner() {
  std::vector<std::string> names;
  for (const auto& p : planners::planner_registry()) names.push_back(p.name);
  for (const char* paper : {"lawnmower", "part-tsp", "part-tsp0", "coop-frontier"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), paper), names.end()) << paper;
  }
  return names;
}

/// A mooring-line-like no-fly box: two columns a third of the way along, from two rows above the
/// middle row (where the default starts are) to the top.
world::CellBox no_fly_box(const world::HullMask& hull) {
  const int x = hull.width() / 3;
  return {x, hull.height() / 2 + 2, x + 1, hull.height() - 1};
}

/// Writes a corrosion map in the text-mask format (rows top first, 'X' corroded).
std::string write_map(const std::string& path, const world::HullMask& hull, auto corroded) {
  std::ostringstream text;
  for (int y = hull.height() - 1; y >= 0; --y) {
    for (int x = 0; x < hull.width(); ++x) {
      text << (hull.is_hull(x, y) && corroded(x, y) ? 'X' : '.');
    }
    text << '\n';
  }
  std::ofstream(path) << text.str();
  return path;
}

struct Variant {
  std::string hull;
  bool no_fly = false;
  bool user_maps = false;
};

std::string variant_name(const ::testing::TestParamInfo<Variant>& info) {
  return info.param.hull + (info.param.no_fly ? "_NoFly" : "_Open") +
         (info.param.user_maps ? "_UserMaps" : "_GeneratedMaps");
}

void PrintTo(const Variant& v, std::ostream* os) {
  *os << v.hull << (v.no_fly ? " with no-fly zones" : " without no-fly zones")
      << (v.user_maps ? ", the user's maps" : ", generated maps");
}

class DoneWhenMatrix : public ::testing::TestWithParam<Variant> {};

TEST_P(DoneWhenMatrix, EveryPlannerCompletesInProcessFromTheCliAndFromAConfig) {
  const Variant& v = GetParam();
  std::string why;
  const MatrixHull* mh = matrix_hull(v.hull, why);
  if (mh == nullptr) GTEST_SKIP() << "the DTC is not installed (" << why << ")";
  const world::HullMask& hull = mh->hull;
  const auto names = every_planner();
  const std::string dir = make_temp_dir("done_when_" + variant_name({v, 0}));

  // The user's maps: corrosion scattered over the hull, a prior that finds half of it and adds
  // false positives.
  std::string prior_path, truth_path;
  if (v.user_maps) {
    const auto truth = [](int x, int y) { return (3 * x + 5 * y) % 29 == 0; };
    truth_path = write_map(dir + "/truth.txt", hull, truth);
    prior_path = write_map(dir + "/prior.txt", hull, [&](int x, int y) {
      return (truth(x, y) && x % 2 == 0) || (3 * x + 5 * y) % 31 == 1;
    });
  }
  const world::CellBox box = no_fly_box(hull);
  const std::vector<world::CellBox> boxes{box};

  for (const auto& algorithm : names) {
    SCOPED_TRACE(algorithm);
    // In process, under the checker.
    planners::MissionSpec spec;
    spec.algorithm = algorithm;
    spec.params.uavs = kUavs;
    spec.params.s2 = kS2;
    if (hull.geometry()) spec.params.cell_size_m = hull.geometry()->cell_size;
    if (v.no_fly) {
      spec.params.no_fly =
          std::make_shared<const world::NoFlyMask>(world::make_no_fly_mask(hull, "", boxes));
    }
    spec.seed = kSeed;
    spec.corrosion = world::scenario("imperfect").corrosion(hull.width());
    spec.maps = world::load_user_maps(prior_path, truth_path, hull);
    MissionChecker checker;
    planners::MissionOptions options;
    options.observers = {&checker};
    const auto r = planners::run_mission(spec, hull, options);
    EXPECT_TRUE(r.complete);
    EXPECT_TRUE(checker.ok());
    EXPECT_GT(checker.steps_checked(), 0);
    if (!v.no_fly) {
      EXPECT_EQ(r.hull_cells, hull.cell_count());
    }

    // From the CLI, with a trace.
    const std::string trace_path = dir + "/" + algorithm + ".json";
    std::vector<std::string> args{
        "run",    "-a", algorithm,    "-n",        "4",      "--s2",    std::to_string(kS2),
        "--seed", "3",  "--scenario", "imperfect", "--json", "--trace", trace_path};
    args.insert(args.end(), mh->cli.begin(), mh->cli.end());
    if (v.no_fly) {
      args.insert(args.end(),
                  {"--no-fly-box", fmt::format("{},{},{},{}", box.x0, box.y0, box.x1, box.y1)});
    }
    if (v.user_maps) args.insert(args.end(), {"--prior", prior_path, "--truth", truth_path});
    const auto cli = run_cli(args);
    ASSERT_EQ(cli.status, 0) << cli.err;
    const json out = json::parse(cli.out);
    EXPECT_EQ(out.at("complete"), true);
    EXPECT_EQ(out.at("T_c"), r.t_c ? json(*r.t_c) : json(nullptr));
    EXPECT_EQ(out.at("T_m"), r.t_m ? json(*r.t_m) : json(nullptr));
    EXPECT_EQ(out.at("steps"), r.steps);
    EXPECT_EQ(out.at("unreachable_cells"), r.unreachable_cells);
    json trace;
    std::ifstream(trace_path) >> trace;
    EXPECT_EQ(trace.at("result").at("complete"), true);
    EXPECT_EQ(trace.contains("no_fly"), v.no_fly);
    if (v.user_maps) {
      EXPECT_EQ(trace.at("parameters").at("truth_file"), truth_path);
      EXPECT_EQ(trace.at("parameters").at("prior_file"), prior_path);
    }
    if (v.no_fly) {  // no UAV is ever on a no-fly position
      const auto& rows = trace.at("no_fly");
      int on_no_fly = 0;
      for (const auto& frame : trace.at("frames")) {
        const auto& u = frame.at("u");
        for (std::size_t k = 0; k + 4 < u.size(); k += 5) {
          const auto& row = rows.at(u[k + 1].get<std::size_t>()).get_ref<const std::string&>();
          on_no_fly += row.at(u[k].get<std::size_t>()) == '#' ? 1 : 0;
        }
      }
      EXPECT_EQ(on_no_fly, 0);
    }
  }

  // From a YAML config: every planner in one experiment.
  std::string config = fmt::format(
      "name: done-when\nhull: {}\nscenarios: [imperfect]\ns2: [{}]\nuavs: [{}]\n"
      "algorithms: [{}]\ninstances: 1\n",
      mh->yaml, kS2, kUavs, fmt::join(names, ", "));
  if (v.no_fly) {
    const double cell = hull.geometry() ? hull.geometry()->cell_size : 0.5;
    config += fmt::format("no-fly: {{boxes-m: [[{}, {}, {}, {}]]}}\n", box.x0 * cell, box.y0 * cell,
                          (box.x1 + 1) * cell, (box.y1 + 1) * cell);
  }
  if (v.user_maps) config += fmt::format("prior: {}\ntruth: {}\n", prior_path, truth_path);
  std::ofstream(dir + "/config.yaml") << config;
  const auto experiment = run_cli(
      {"experiment", "--config", dir + "/config.yaml", "--out", dir + "/results", "--jobs", "1"});
  ASSERT_EQ(experiment.status, 0) << experiment.err << "\n" << config;
  std::ifstream runs_file(dir + "/results/runs.csv");
  const std::string runs_text((std::istreambuf_iterator<char>(runs_file)),
                              std::istreambuf_iterator<char>());
  const auto runs = experiment::parse_csv(runs_text, "runs.csv");
  const auto c_algorithm = static_cast<std::size_t>(runs.column("algorithm", "runs.csv"));
  const auto c_complete = static_cast<std::size_t>(runs.column("complete", "runs.csv"));
  const auto c_unreachable = static_cast<std::size_t>(runs.column("unreachable_cells", "runs.csv"));
  std::set<std::string> ran;
  for (const auto& row : runs.rows) {
    ran.insert(row[c_algorithm]);
    EXPECT_EQ(row[c_complete], "1") << row[c_algorithm];
    if (!v.no_fly) {
      EXPECT_EQ(row[c_unreachable], "0") << row[c_algorithm];
    }
  }
  EXPECT_EQ(ran, std::set<std::string>(names.begin(), names.end()));
}

std::vector<Variant> every_variant() {
  std::vector<Variant> out;
  for (const char* hull : {"default", "wigley", "dtc"}) {
    for (bool no_fly : {false, true}) {
      for (bool maps : {false, true}) out.push_back({hull, no_fly, maps});
    }
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Hulls, DoneWhenMatrix, ::testing::ValuesIn(every_variant()), variant_name);

}  // namespace
}  // namespace hullinspect::testing
