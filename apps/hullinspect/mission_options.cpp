#include "mission_options.hpp"

#include <fmt/format.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/scenario.hpp"

namespace hullinspect::cli {

void add_mission_options(CLI::App& cmd, MissionArgs& a) {
  cmd.add_option("--algorithm,-a", a.algorithm,
                 "Planner: lawnmower, part-tsp, part-tsp0, coop-frontier")
      ->capture_default_str();
  cmd.add_option("--uavs,-n", a.uavs, "Fleet size n (1 … number of hull cells)")->capture_default_str();
  cmd.add_option("--s1", a.s1, "Footprint side at the close-up plane z = 1, cells (odd)")
      ->capture_default_str();
  cmd.add_option("--s2", a.s2, "Footprint side at the detection plane z = 2, cells (odd, > s1)")
      ->capture_default_str();
  cmd.add_option("--theta", a.theta, "Camera aperture θ in degrees, in (0, 180)")->capture_default_str();
  cmd.add_option("--start-z", a.start_z, "Plane every UAV starts on (1 or 2)")->capture_default_str();
  cmd.add_option("--start", a.starts,
                 "Start cell x,y of each UAV (repeat once per UAV; default: spread along the hull)")
      ->type_name("X,Y");
  cmd.add_option("--seed", a.seed, "Instance seed (same seed, same C and C')")->capture_default_str();
  cmd.add_option("--scenario", a.scenario,
                 "Corrosion scenario preset: perfect, imperfect, inhomogeneous, combined "
                 "(explicit --p-c/--l-c/--p-tp/--p-fp override it)");
  cmd.add_option("--p-c", a.p_c, "Probability that a hull cell is a corrosion centre [0, 1] (default 0.005)");
  cmd.add_option("--l-c", a.l_c, "Largest corrosion rectangle side, odd (default 5)");
  cmd.add_option("--front-p-c", a.front_p_c,
                 "p_C of the front half (x >= a/2); --p-c then applies to the back half");
  cmd.add_option("--front-l-c", a.front_l_c, "l_C of the front half (x >= a/2)");
  cmd.add_option("--p-tp", a.p_tp, "Probability that a true centre is in the prior [0, 1] (default 1)");
  cmd.add_option("--p-fp", a.p_fp,
                 "Probability that another hull cell is a false prior centre [0, 1] (default 0)");
  cmd.add_option("--hull", a.hull,
                 "Hull: 'default', 'dtc', a text mask, a PGM image, a hull JSON or a mesh "
                 "(STL/OBJ/PLY, optionally .gz; see docs/hulls.md)")
      ->type_name("FILE")
      ->capture_default_str();
  cmd.add_option("--time-limit", a.time_limit,
                 "Steps after which an unfinished mission is reported incomplete")
      ->capture_default_str();
  cmd.add_option("--partitioner", a.partitioner, "Partitioner for partitioned planners: darp, stripes");
  cmd.add_option("--partition-seed", a.partition_seed, "Seed of the partitioner (default 0)");
  cmd.add_option("--tsp-solver", a.tsp_solver, "Part-TSP: TSP solver (exact, dfj-iterative, heuristic)");
  cmd.add_option("--r1", a.r1, "Part-TSP: steps after the last detection before descending (default 2)");
  cmd.add_option("--r2", a.r2, "Part-TSP: steps after the last inspection before ascending (default 0)");
  cmd.add_option("--alpha", a.alpha, "Coop-Frontier: weight α of the prior term in eq. 13");
  cmd.add_option("--beta", a.beta, "Coop-Frontier: weight β of the distance term in eq. 15");
  cmd.add_option("--fail", a.fail,
                 "UAV k fails at the start of step T: it stops, senses nothing (repeatable; "
                 "docs/beyond.md)")
      ->type_name("UAV@T");
  cmd.add_option("--fail-rate", a.fail_rate,
                 "Probability that a working UAV fails at a step, drawn from the instance seed")
      ->capture_default_str();
  cmd.add_option("--fail-one-within", a.fail_one_within,
                 "One UAV (drawn from the instance seed) fails at a random step below H (0: none)")
      ->type_name("H")
      ->capture_default_str();
  cmd.add_option("--option,-O", a.planner_options, "Any other planner option as key=value (repeatable)")
      ->type_name("KEY=VALUE");
  cmd.add_option("--prior", a.prior,
                 "Expected corrosion C' from FILE (text mask or PGM, marked = corroded) instead of "
                 "the generated prior")
      ->type_name("FILE");
  cmd.add_option("--truth", a.truth,
                 "Ground truth C from FILE (text mask or PGM, marked = corroded) instead of the "
                 "generated one")
      ->type_name("FILE");
  add_mesh_options(cmd, a.mesh);
}

world::HullMask load_mission_hull(const MissionArgs& a) {
  return load_hull_argument(a.hull, a.mesh);
}

namespace {
grid::Cell parse_cell(const std::string& text) {
  int x = 0;
  int y = 0;
  char comma = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%d %c %d %c", &x, &comma, &y, &extra) != 3 || comma != ',') {
    throw ParameterError("start", fmt::format("expects X,Y (got '{}')", text));
  }
  return {x, y};
}
}  // namespace

planners::MissionSpec build_spec(const MissionArgs& a, const world::HullMask& hull) {
  planners::MissionSpec spec;
  spec.algorithm = a.algorithm;
  spec.seed = a.seed;
  auto& p = spec.params;
  p.uavs = a.uavs;
  p.s1 = a.s1;
  p.s2 = a.s2;
  p.theta_deg = a.theta;
  p.start_z = a.start_z;
  p.time_limit = a.time_limit;
  if (hull.geometry()) p.cell_size_m = hull.geometry()->cell_size;
  for (const auto& s : a.starts) p.starts.push_back(parse_cell(s));

  planners::Scenario sc{"custom", "", 0.005, 0.005, 5, 5, 1.0, 0.0};
  if (!a.scenario.empty()) sc = planners::scenario(a.scenario);
  if (a.p_c) sc.back_p_c = sc.front_p_c = *a.p_c;
  if (a.l_c) sc.back_l_c = sc.front_l_c = *a.l_c;
  if (a.front_p_c) sc.front_p_c = *a.front_p_c;
  if (a.front_l_c) sc.front_l_c = *a.front_l_c;
  if (a.p_tp) sc.p_tp = *a.p_tp;
  if (a.p_fp) sc.p_fp = *a.p_fp;
  spec.corrosion = sc.corrosion(hull.width());
  spec.maps = world::load_user_maps(a.prior, a.truth, hull);

  auto put = [&](const char* key, const std::optional<std::string>& v) {
    if (v) spec.planner_options[key] = *v;
  };
  put("partitioner", a.partitioner);
  put("partition-seed", a.partition_seed);
  put("tsp-solver", a.tsp_solver);
  put("r1", a.r1);
  put("r2", a.r2);
  put("alpha", a.alpha);
  put("beta", a.beta);
  for (const auto& f : a.fail) spec.failures.at.push_back(world::parse_uav_failure(f));
  spec.failures.rate = a.fail_rate;
  spec.failures.one_within = a.fail_one_within;
  for (const auto& kv : a.planner_options) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw ParameterError("option", fmt::format("expects KEY=VALUE (got '{}')", kv));
    }
    spec.planner_options[kv.substr(0, eq)] = kv.substr(eq + 1);
  }
  return spec;
}

}  // namespace hullinspect::cli
