#include "mission_options.hpp"

#include <fmt/format.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/parameters.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/defect_map.hpp"
#include "hullinspect/world/no_fly.hpp"
#include "hullinspect/world/scenario.hpp"
#include "number_options.hpp"

namespace hullinspect::cli {

namespace {

/// "desc (type, default D, range)" of a declared option, for --help.
std::string declared_help(const std::vector<ParamSpec>& specs, std::string_view name,
                          std::string_view prefix = "") {
  for (const auto& s : specs) {
    if (s.name != name) continue;
    std::string text = std::string(prefix) + s.description + " (" +
                       std::string(param_type_name(s.type)) + ", default " + s.default_value;
    if (!s.range.empty() && s.type != ParamType::kBool) text += ", " + s.range;
    return text + ")";
  }
  return std::string(prefix);
}

std::vector<ParamSpec> planner_specs(std::string_view planner) {
  return planners::planners().get(planner).specs();
}

}  // namespace

void add_mission_options(CLI::App& cmd, MissionArgs& a) {
  std::string planner_names;
  std::string planner_help;
  for (const auto& info : planners::planner_registry()) {
    planner_names += (planner_names.empty() ? "" : ", ") + info.name;
    planner_help += fmt::format("  {}: {}\n{}", info.name, info.description,
                                describe_params(info.options, "    "));
  }
  std::string scenario_names;
  for (const auto& n : world::scenarios().names()) {
    scenario_names += (scenario_names.empty() ? "" : ", ") + n;
  }
  const auto scenario = world::scenarios().get("perfect").specs();
  cmd.add_option("--algorithm,-a", a.algorithm, "Planner: " + planner_names)->capture_default_str();
  cmd.add_option("--uavs,-n", a.uavs, "Fleet size n (1 … number of hull cells)")
      ->capture_default_str();
  cmd.add_option("--s1", a.s1, "Footprint side at the close-up plane z = 1, cells (odd)")
      ->capture_default_str();
  cmd.add_option("--s2", a.s2, "Footprint side at the detection plane z = 2, cells (odd, > s1)")
      ->capture_default_str();
  cmd.add_option("--theta", a.theta, "Camera aperture θ in degrees, in (0, 180)")
      ->capture_default_str();
  cmd.add_option("--start-z", a.start_z, "Plane every UAV starts on (1 or 2)")
      ->capture_default_str();
  cmd.add_option("--start", a.starts,
                 "Start cell x,y of each UAV (repeat once per UAV; default: spread along the hull)")
      ->type_name("X,Y");
  cmd.add_option("--seed", a.seed, "Instance seed (same seed, same C and C')")
      ->capture_default_str();
  cmd.add_option("--scenario", a.scenario,
                 "Corrosion scenario: " + scenario_names +
                     " (--p-c/--l-c/--front-p-c/--front-l-c/--p-tp/--p-fp override its values; "
                     "defaults below are perfect's, see `hullinspect list scenarios`)")
      ->capture_default_str();
  cmd.add_option("--p-c", a.p_c, declared_help(scenario, "p-c"))->type_name("P");
  cmd.add_option("--l-c", a.l_c, declared_help(scenario, "l-c"))->type_name("L");
  cmd.add_option("--front-p-c", a.front_p_c, declared_help(scenario, "front-p-c"))->type_name("P");
  cmd.add_option("--front-l-c", a.front_l_c, declared_help(scenario, "front-l-c"))->type_name("L");
  cmd.add_option("--p-tp", a.p_tp, declared_help(scenario, "p-tp"))->type_name("P");
  cmd.add_option("--p-fp", a.p_fp, declared_help(scenario, "p-fp"))->type_name("P");
  cmd.add_option("--hull", a.hull,
                 "Hull: 'default', 'dtc', a text mask, a PGM image, a hull JSON or a mesh "
                 "(STL/OBJ/PLY, optionally .gz; see docs/hulls.md)")
      ->type_name("FILE")
      ->capture_default_str();
  cmd.add_option("--time-limit", a.time_limit,
                 "Steps after which an unfinished mission is reported incomplete")
      ->capture_default_str();
  cmd.add_option("--separation", a.separation,
                 "Separation D in cells: two UAVs conflict when max(|dx|, |dy|) < D, whatever "
                 "their planes (0: no separation, the paper's model; docs/model.md)")
      ->capture_default_str();
  cmd.add_flag("--strict-separation", a.strict_separation,
               "A separation conflict is a mission error (exit 1) instead of a count");
  cmd.add_flag("--no-deconfliction", a.no_deconfliction,
               "With --separation: fly the planner's actions as they are (conflicts are counted) "
               "instead of through the deconfliction layer");
  const auto part_tsp = planner_specs("part-tsp");
  const auto coop = planner_specs("coop-frontier");
  cmd.add_option("--partitioner", a.partitioner,
                 declared_help(part_tsp, "partitioner", "Partitioned planners: "))
      ->type_name("NAME");
  cmd.add_option("--partition-seed", a.partition_seed,
                 declared_help(part_tsp, "partition-seed", "Partitioned planners: "))
      ->type_name("SEED");
  cmd.add_option("--tsp-solver", a.tsp_solver, declared_help(part_tsp, "tsp-solver", "Part-TSP: "))
      ->type_name("NAME");
  cmd.add_option("--r1", a.r1, declared_help(part_tsp, "r1", "Part-TSP: "))->type_name("STEPS");
  cmd.add_option("--r2", a.r2, declared_help(part_tsp, "r2", "Part-TSP: "))->type_name("STEPS");
  cmd.add_option("--alpha", a.alpha, declared_help(coop, "alpha", "Coop-Frontier: "))
      ->type_name("X");
  cmd.add_option("--beta", a.beta, declared_help(coop, "beta", "Coop-Frontier: "))->type_name("X");
  cmd.add_option("--option,-O", a.planner_options,
                 "Any planner option as key=value (repeatable; listed below, also "
                 "`hullinspect list planners`)")
      ->type_name("KEY=VALUE");
  cmd.add_option("--fail", a.fail,
                 "UAV k fails at the start of step T: it stops, senses nothing (repeatable; "
                 "docs/failures.md)")
      ->type_name("UAV@T");
  cmd.add_option("--fail-rate", a.fail_rate,
                 "Probability that a working UAV fails at a step, drawn from the instance seed")
      ->capture_default_str();
  cmd.add_option("--fail-one-within", a.fail_one_within,
                 "One UAV (drawn from the instance seed) fails at a random step below H (0: none)")
      ->type_name("H")
      ->capture_default_str();
  auto* prior =
      cmd.add_option(
             "--prior", a.prior,
             "Expected corrosion C' from FILE (text mask or PGM, marked = corroded) instead of "
             "the generated prior")
          ->type_name("FILE");
  auto* truth = cmd.add_option("--truth", a.truth,
                               "Ground truth C from FILE (text mask or PGM, marked = corroded) "
                               "instead of the generated one")
                    ->type_name("FILE");
  cmd.add_option("--prior-defects", a.prior_defects,
                 "Expected corrosion C' from a list of defects in ship coordinates (CSV or JSON: "
                 "x_m or frame, z_m, side, w_m, h_m; docs/hulls.md)")
      ->type_name("FILE")
      ->excludes(prior);
  cmd.add_option("--truth-defects", a.truth_defects,
                 "Ground truth C from a list of defects in ship coordinates (as --prior-defects)")
      ->type_name("FILE")
      ->excludes(truth);
  cmd.add_option("--frame-spacing", a.frame_spacing,
                 "Metres between frames, for defects placed by frame number (frame 0 at x = 0)")
      ->type_name("M")
      ->check(real_in(1e-3, 1e3));
  cmd.add_option("--launch", a.launch,
                 "A launch site: a non-hull or grid-edge cell where UAVs take off and land "
                 "(repeatable; each UAV uses the site nearest its start cell; T_m is then the time "
                 "the last UAV has landed; docs/model.md)")
      ->type_name("X,Y");
  cmd.add_option("--launch-transfer", a.launch_transfer,
                 "Seconds each way between a launch site and the quay or deck beyond the grid")
      ->type_name("S")
      ->capture_default_str();
  cmd.add_option("--takeoff-time", a.takeoff_time,
                 "Seconds from the ground to plane 2 at a launch site, and back down (default: a "
                 "plane change, u_z)")
      ->type_name("S");
  add_battery_options(cmd, a.battery);
  add_mesh_options(cmd, a.mesh);
  add_no_fly_options(cmd, a.no_fly, a.no_fly_boxes);
  cmd.footer("Planners and their options (-O KEY=VALUE):\n" + planner_help);
}

void add_no_fly_options(CLI::App& cmd, std::string& file, std::vector<std::string>& boxes) {
  cmd.add_option("--no-fly", file,
                 "No-fly positions: a mask the hull's size (text or PGM; hull-marked cells are "
                 "no-fly; see docs/model.md)")
      ->type_name("FILE");
  cmd.add_option("--no-fly-box", boxes,
                 "A no-fly rectangle of cells, corners inclusive (repeatable)")
      ->type_name("X0,Y0,X1,Y1");
}

std::shared_ptr<const grid::Grid<std::uint8_t>> build_no_fly(const std::string& file,
                                                             const std::vector<std::string>& boxes,
                                                             const world::HullMask& hull) {
  if (file.empty() && boxes.empty()) return nullptr;
  std::vector<world::CellBox> cell_boxes;
  for (const auto& b : boxes) cell_boxes.push_back(world::parse_cell_box(b, "no-fly-box"));
  return std::make_shared<const grid::Grid<std::uint8_t>>(
      world::make_no_fly_mask(hull, file, cell_boxes));
}

world::HullMask load_mission_hull(const MissionArgs& a) {
  return load_hull_argument(a.hull, a.mesh);
}

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
  p.separation = a.separation;
  p.strict_separation = a.strict_separation;
  p.deconflict = !a.no_deconfliction;
  if (hull.geometry()) p.cell_size_m = hull.geometry()->cell_size;
  for (const auto& s : a.starts) p.starts.push_back(parse_xy(s));
  p.no_fly = build_no_fly(a.no_fly, a.no_fly_boxes, hull);
  for (const auto& s : a.launch) p.launch_sites.push_back(parse_xy(s, "launch"));
  p.launch_transfer_s = a.launch_transfer;
  p.takeoff_time_s = a.takeoff_time;
  apply_battery_args(a.battery, p);

  OptionMap scenario_options;
  auto set = [&](const char* key, const std::optional<std::string>& v) {
    if (v) scenario_options[key] = *v;
  };
  set("p-c", a.p_c);
  set("l-c", a.l_c);
  set("front-p-c", a.front_p_c);
  set("front-l-c", a.front_l_c);
  set("p-tp", a.p_tp);
  set("p-fp", a.p_fp);
  try {
    spec.corrosion = world::scenario(a.scenario, scenario_options).corrosion(hull.width());
  } catch (const ParameterError& e) {
    // "perfect.p-c" is --p-c on this command line.
    const auto dot = e.name().find('.');
    if (dot == std::string::npos) throw;
    throw ParameterError(e.name().substr(dot + 1), e.problem());
  }
  spec.maps = world::load_user_maps(a.prior, a.truth, hull);
  world::FrameSpacing frames;
  frames.frame_spacing_m = a.frame_spacing;
  if (!a.prior_defects.empty()) {
    spec.maps.prior = std::make_shared<const world::CorrosionMap>(
        world::load_defect_map(a.prior_defects, hull, frames));
  }
  if (!a.truth_defects.empty()) {
    spec.maps.truth = std::make_shared<const world::CorrosionMap>(
        world::load_defect_map(a.truth_defects, hull, frames));
  }

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
