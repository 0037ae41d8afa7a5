#include "hullinspect/planners/mission_input.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <iostream>
#include <limits>
#include <optional>
#include <string_view>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/integer_of_range.hpp"
#include "hullinspect/core/numbers.hpp"
#include "hullinspect/core/parameters.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/defect_map.hpp"
#include "hullinspect/world/failures.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "hullinspect/world/no_fly.hpp"
#include "hullinspect/world/scenario.hpp"

namespace hullinspect::planners {

namespace {

using Setter = std::function<void(MissionInput&, const std::string&)>;

constexpr const char* kMeshGroup = "Mesh hulls (see docs/hulls.md)";

/// Runs `parse`, turning the shared parser's NumberError into ParameterError(key, its message).
template <class Parse>
auto exact(const std::string& key, Parse parse) {
  try {
    return parse();
  } catch (const NumberError& e) {
    throw ParameterError(key, e.what());
  }
}

/// YAML's spellings of the non-finite reals (.nan, .inf, -.inf, +.inf, any letter case), which
/// std::from_chars does not read: a config's `.nan` then reaches the mission's validation as the
/// command line's `nan` does, and both are refused with the option's range.
std::optional<double> yaml_non_finite(std::string_view text) {
  std::string lower;
  for (const char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == ".nan") return std::numeric_limits<double>::quiet_NaN();
  if (lower == ".inf" || lower == "+.inf") return std::numeric_limits<double>::infinity();
  if (lower == "-.inf") return -std::numeric_limits<double>::infinity();
  return std::nullopt;
}

/// A real read as any C++ literal, "nan" and "inf" included (and YAML's .nan/.inf): for the
/// options whose range the mission's validation checks with its own message ("must be a number
/// of seconds …"), so every spelling of a value out of range gets that one message.
double literal_real(const std::string& key, const std::string& text) {
  if (const auto non_finite = yaml_non_finite(text)) return *non_finite;
  double value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) {
    throw ParameterError(key, fmt::format("must be a number (got '{}')", escape_for_message(text)));
  }
  return value;
}

std::string shown(double value) {
  return fmt::format("{}", value);
}

/// "desc (type, default D, range)" of a declared planner or scenario option, for --help.
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

/// The declarations, built once (their help texts list the registered planners and scenarios).
std::vector<MissionOptionDecl> declare() {
  const MissionInput d;
  const world::MeshImportOptions mesh;
  std::vector<MissionOptionDecl> out;
  auto add = [&out](std::string key, std::string value_name, InputKind kind, std::string help,
                    Setter set, std::string shown_default = "") -> MissionOptionDecl& {
    MissionOptionDecl decl;
    decl.key = std::move(key);
    decl.value_name = std::move(value_name);
    decl.kind = kind;
    decl.help = std::move(help);
    decl.set = std::move(set);
    decl.shown_default = std::move(shown_default);
    return out.emplace_back(std::move(decl));
  };
  // Setters by the field's type; `key` names the option in errors.
  // [min, max] is the option's own range: text that is no integer ("x", "1e3", 10^11) is refused
  // naming it; an integer outside it reaches the mission's validation, whose message names the
  // range with its reason ("must be at least 1", "must be 1 or 2").
  auto integer = [](const std::string& key, int MissionInput::*field, int min,
                    int max = std::numeric_limits<int>::max()) -> Setter {
    return [key, field, min, max](MissionInput& in, const std::string& t) {
      in.*field = exact(key, [&] { return parse_integer_of_range<int>(t, min, max); });
    };
  };
  auto real = [](const std::string& key, double MissionInput::*field) -> Setter {
    return [key, field](MissionInput& in, const std::string& t) {
      in.*field = exact(key, [&] { return parse_real(t); });
    };
  };
  auto text = [](std::string MissionInput::*field) -> Setter {
    return [field](MissionInput& in, const std::string& t) { in.*field = t; };
  };
  auto maybe_text = [](std::optional<std::string> MissionInput::*field) -> Setter {
    return [field](MissionInput& in, const std::string& t) { in.*field = t; };
  };
  auto each = [](std::vector<std::string> MissionInput::*field) -> Setter {
    return [field](MissionInput& in, const std::string& t) { (in.*field).push_back(t); };
  };
  auto flag = [](bool MissionInput::*field) -> Setter {
    return [field](MissionInput& in, const std::string&) { in.*field = true; };
  };

  std::string planner_names;
  std::string scenario_names;
  for (const auto& info : planner_registry()) {
    planner_names += (planner_names.empty() ? "" : ", ") + info.name;
  }
  for (const auto& n : world::scenarios().names()) {
    scenario_names += (scenario_names.empty() ? "" : ", ") + n;
  }
  const auto scenario = world::scenarios().get("perfect").specs();
  const auto part_tsp = planners().get("part-tsp").specs();
  const auto coop = planners().get("coop-frontier").specs();

  add("algorithm", "TEXT", InputKind::kValue, "Planner: " + planner_names,
      text(&MissionInput::algorithm), d.algorithm)
      .alias = "a";
  auto& uavs =
      add("uavs", "INT", InputKind::kValue, "Fleet size n (1 … number of hull cells)",
          integer("uavs", &MissionInput::uavs, 1, world::kMaxGridSide * world::kMaxGridSide),
          std::to_string(d.uavs));
  uavs.alias = "n";
  uavs.config_key = "uavs";
  uavs.config_axis = true;
  add("s1", "INT", InputKind::kValue, "Footprint side at the close-up plane z = 1, cells (odd)",
      integer("s1", &MissionInput::s1, 1, world::kMaxFootprintSide - 2), std::to_string(d.s1))
      .config_key = "s1";
  auto& s2 =
      add("s2", "INT", InputKind::kValue,
          "Footprint side at the detection plane z = 2, cells (odd, > s1)",
          integer("s2", &MissionInput::s2, 3, world::kMaxFootprintSide), std::to_string(d.s2));
  s2.config_key = "s2";
  s2.config_axis = true;
  add("theta", "FLOAT", InputKind::kValue, "Camera aperture θ in degrees, in (0, 180)",
      real("theta", &MissionInput::theta), shown(d.theta))
      .config_key = "theta";
  add("start-z", "INT", InputKind::kValue, "Plane every UAV starts on (1 or 2)",
      integer("start-z", &MissionInput::start_z, 1, 2), std::to_string(d.start_z))
      .config_key = "start_z";
  add("start", "X,Y", InputKind::kRepeated,
      "Start cell x,y of each UAV (repeat once per UAV; default: spread along the hull)",
      each(&MissionInput::starts));
  add(
      "seed", "UINT", InputKind::kValue, "Instance seed (same seed, same C and C')",
      [](MissionInput& in, const std::string& t) {
        in.seed = exact("seed", [&] { return parse_integer<std::uint64_t>(t); });
      },
      std::to_string(d.seed));
  add("scenario", "TEXT", InputKind::kValue,
      "Corrosion scenario: " + scenario_names +
          " (--p-c/--l-c/--front-p-c/--front-l-c/--p-tp/--p-fp override its values; "
          "defaults below are perfect's, see `hullinspect list scenarios`)",
      text(&MissionInput::scenario), d.scenario);
  add("p-c", "P", InputKind::kValue, declared_help(scenario, "p-c"),
      maybe_text(&MissionInput::p_c));
  add("l-c", "L", InputKind::kValue, declared_help(scenario, "l-c"),
      maybe_text(&MissionInput::l_c));
  add("front-p-c", "P", InputKind::kValue, declared_help(scenario, "front-p-c"),
      maybe_text(&MissionInput::front_p_c));
  add("front-l-c", "L", InputKind::kValue, declared_help(scenario, "front-l-c"),
      maybe_text(&MissionInput::front_l_c));
  add("p-tp", "P", InputKind::kValue, declared_help(scenario, "p-tp"),
      maybe_text(&MissionInput::p_tp));
  add("p-fp", "P", InputKind::kValue, declared_help(scenario, "p-fp"),
      maybe_text(&MissionInput::p_fp));
  add("hull", "FILE", InputKind::kValue,
      "Hull: 'default', 'dtc', a text mask, a PGM image, a hull JSON or a mesh "
      "(STL/OBJ/PLY, optionally .gz; see docs/hulls.md)",
      text(&MissionInput::hull), d.hull);
  add("time-limit", "INT", InputKind::kValue,
      "Steps after which an unfinished mission is reported incomplete",
      integer("time-limit", &MissionInput::time_limit, 1), std::to_string(d.time_limit))
      .config_key = "time_limit";
  add("separation", "INT", InputKind::kValue,
      "Separation D in cells: two UAVs conflict when max(|dx|, |dy|) < D, whatever "
      "their planes (0: no separation, the paper's model; docs/model.md)",
      integer("separation", &MissionInput::separation, 0), std::to_string(d.separation))
      .config_key = "separation";
  add("strict-separation", "", InputKind::kFlag,
      "A separation conflict is a mission error (exit 1) instead of a count",
      flag(&MissionInput::strict_separation));
  add("no-deconfliction", "", InputKind::kFlag,
      "With --separation: fly the planner's actions as they are (conflicts are counted) "
      "instead of through the deconfliction layer",
      flag(&MissionInput::no_deconfliction));
  add("partitioner", "NAME", InputKind::kValue,
      declared_help(part_tsp, "partitioner", "Partitioned planners: "),
      maybe_text(&MissionInput::partitioner));
  add("partition-seed", "SEED", InputKind::kValue,
      declared_help(part_tsp, "partition-seed", "Partitioned planners: "),
      maybe_text(&MissionInput::partition_seed));
  add("tsp-solver", "NAME", InputKind::kValue, declared_help(part_tsp, "tsp-solver", "Part-TSP: "),
      maybe_text(&MissionInput::tsp_solver));
  add("r1", "STEPS", InputKind::kValue, declared_help(part_tsp, "r1", "Part-TSP: "),
      maybe_text(&MissionInput::r1));
  add("r2", "STEPS", InputKind::kValue, declared_help(part_tsp, "r2", "Part-TSP: "),
      maybe_text(&MissionInput::r2));
  add("alpha", "X", InputKind::kValue, declared_help(coop, "alpha", "Coop-Frontier: "),
      maybe_text(&MissionInput::alpha));
  add("beta", "X", InputKind::kValue, declared_help(coop, "beta", "Coop-Frontier: "),
      maybe_text(&MissionInput::beta));
  add("option", "KEY=VALUE", InputKind::kRepeated,
      "Any planner option as key=value (repeatable; listed below, also "
      "`hullinspect list planners`)",
      each(&MissionInput::planner_options))
      .alias = "O";
  add("fail", "UAV@T", InputKind::kRepeated,
      "UAV k fails at the start of step T: it stops, senses nothing (repeatable; "
      "docs/failures.md)",
      each(&MissionInput::fail));
  add("fail-rate", "FLOAT", InputKind::kValue,
      "Probability that a working UAV fails at a step, drawn from the instance seed",
      real("fail-rate", &MissionInput::fail_rate), shown(d.fail_rate));
  add(
      "fail-one-within", "H", InputKind::kValue,
      "One UAV (drawn from the instance seed) fails at a random step below H (0: none)",
      [](MissionInput& in, const std::string& t) {
        in.fail_one_within = exact("fail-one-within", [&] {
          return parse_integer_of_range<int>(t, 0, std::numeric_limits<int>::max());
        });
      },
      std::to_string(d.fail_one_within));
  add("prior", "FILE", InputKind::kValue,
      "Expected corrosion C' from FILE (text mask or PGM, marked = corroded) instead of "
      "the generated prior",
      text(&MissionInput::prior));
  add("truth", "FILE", InputKind::kValue,
      "Ground truth C from FILE (text mask or PGM, marked = corroded) "
      "instead of the generated one",
      text(&MissionInput::truth));
  add("prior-defects", "FILE", InputKind::kValue,
      "Expected corrosion C' from a list of defects in ship coordinates (CSV or JSON: "
      "x_m or frame, z_m, side, w_m, h_m; docs/hulls.md)",
      text(&MissionInput::prior_defects))
      .excludes = "prior";
  add("truth-defects", "FILE", InputKind::kValue,
      "Ground truth C from a list of defects in ship coordinates (as --prior-defects)",
      text(&MissionInput::truth_defects))
      .excludes = "truth";
  add("frame-spacing", "M", InputKind::kValue,
      "Metres between frames, for defects placed by frame number (frame 0 at x = 0)",
      [](MissionInput& in, const std::string& t) {
        in.frame_spacing = exact("frame-spacing", [&] { return parse_real(t, 1e-3, 1e3); });
      })
      .config_key = "frame-spacing";
  add("launch", "X,Y", InputKind::kRepeated,
      "A launch site: a non-hull or grid-edge cell where UAVs take off and land "
      "(repeatable; each UAV uses the site nearest its start cell; T_m is then the time "
      "the last UAV has landed; docs/model.md)",
      each(&MissionInput::launch));
  add(
      "launch-transfer", "S", InputKind::kValue,
      "Seconds each way between a launch site and the quay or deck beyond the grid",
      [](MissionInput& in, const std::string& t) {
        in.launch_transfer = literal_real("launch-transfer", t);
      },
      shown(d.launch_transfer))
      .config_key = "launch.transfer";
  add("takeoff-time", "S", InputKind::kValue,
      "Seconds from the ground to plane 2 at a launch site, and back down (default: a "
      "plane change, u_z)",
      [](MissionInput& in, const std::string& t) {
        in.takeoff_time = literal_real("takeoff-time", t);
      })
      .config_key = "launch.takeoff-time";
  add("endurance", "S", InputKind::kValue,
      "Seconds of flight per battery (default: unlimited, the paper's model); needs --launch: a "
      "UAV is sent home to swap its battery before it runs low, and one airborne with an empty "
      "battery crashes (docs/model.md)",
      [](MissionInput& in, const std::string& t) { in.endurance = literal_real("endurance", t); })
      .config_key = "battery.endurance";
  add("reserve", "S", InputKind::kValue,
      "With --endurance: seconds of flight a UAV keeps for landing (default: 10 % of the "
      "endurance)",
      [](MissionInput& in, const std::string& t) { in.reserve = literal_real("reserve", t); })
      .config_key = "battery.reserve";
  add(
      "swap-time", "S", InputKind::kValue,
      "With --endurance: seconds on the ground at a launch site to swap a battery",
      [](MissionInput& in, const std::string& t) { in.swap_time = literal_real("swap-time", t); },
      shown(d.swap_time))
      .config_key = "battery.swap-time";
  add("speed", "M/S", InputKind::kValue,
      "Horizontal speed in m/s: a move to a neighbouring cell takes cell / speed seconds, the "
      "length of one step (default: one cell per second)",
      [](MissionInput& in, const std::string& t) { in.speed = literal_real("speed", t); })
      .config_key = "speed";
  add("climb-speed", "M/S", InputKind::kValue,
      "Climb speed in m/s for plane changes and the take-off, rounded up to whole steps "
      "(default: one cell per second, u_z steps at the default speed)",
      [](MissionInput& in, const std::string& t) {
        in.climb_speed = literal_real("climb-speed", t);
      })
      .config_key = "climb-speed";

  // How a mesh --hull is imported. The defaults shown are MeshImportOptions{}'s (mesh_hull.hpp);
  // the inputs stay unset so that a named mesh hull can start from its own.
  const std::size_t mesh_begin = out.size();
  auto mesh_real = [](const std::string& key, std::optional<double> MeshInput::*field) -> Setter {
    return [key, field](MissionInput& in, const std::string& t) {
      in.mesh.*field = exact(key, [&] { return parse_real(t); });
    };
  };
  add(
      "side", "TEXT", InputKind::kValue,
      "Side inspected: port, starboard, or both (the whole hull unrolled into one grid)",
      [](MissionInput& in, const std::string& t) { in.mesh.side = t; },
      std::string(world::to_string(mesh.side)))
      .also = "sides";
  add("cell-size", "FLOAT", InputKind::kValue, "Cell side in metres",
      mesh_real("cell-size", &MeshInput::cell_size), shown(mesh.cell_size));
  add("scale", "FLOAT", InputKind::kValue, "Uniform scale applied to the file's coordinates",
      mesh_real("scale", &MeshInput::scale), shown(mesh.scale));
  add(
      "axes", "TEXT", InputKind::kValue,
      "Ship x,y,z (stern→bow, to port, up) as signed file axes, e.g. x,-z,y",
      [](MissionInput& in, const std::string& t) { in.mesh.axes = t; }, mesh.axes.to_string());
  add("waterline", "Z", InputKind::kValue,
      "Ship-frame Z in metres below which cells are not hull" +
          std::string(mesh.waterline ? "" : " (default: none, a hull in dry dock)"),
      mesh_real("waterline", &MeshInput::waterline), mesh.waterline ? shown(*mesh.waterline) : "");
  add("min-coverage", "FLOAT", InputKind::kValue,
      "Fraction of a cell that must be surface for it to be hull, in (0, 1]",
      mesh_real("min-coverage", &MeshInput::min_coverage), shown(mesh.min_coverage));
  add("keep-largest", "", InputKind::kFlag,
      "Keep the largest 4-connected part of the projection (else an error)",
      [](MissionInput& in, const std::string&) { in.mesh.keep_largest = true; });
  add("include", "transom", InputKind::kRepeated,
      "With --sides both: also unroll the transom (closing the grid around the stern)",
      [](MissionInput& in, const std::string& t) { in.mesh.include.push_back(t); })
      .delimiter = ',';
  add("max-area-error", "FLOAT", InputKind::kValue,
      "With --sides both: refuse an import whose worst cell-area error is above this "
      "fraction (0.1 is 10 %; default: no limit)",
      mesh_real("max-area-error", &MeshInput::max_area_error));
  for (std::size_t i = mesh_begin; i < out.size(); ++i) out[i].group = kMeshGroup;

  add("no-fly", "FILE", InputKind::kValue,
      "No-fly positions: a mask the hull's size (text or PGM; hull-marked cells are "
      "no-fly; see docs/model.md)",
      text(&MissionInput::no_fly));
  add("no-fly-box", "X0,Y0,X1,Y1", InputKind::kRepeated,
      "A no-fly rectangle of cells, corners inclusive (repeatable)",
      each(&MissionInput::no_fly_boxes));
  return out;
}

}  // namespace

const std::vector<MissionOptionDecl>& mission_option_declarations() {
  static const std::vector<MissionOptionDecl> declarations = declare();
  return declarations;
}

std::vector<const MissionOptionDecl*> mesh_option_declarations() {
  std::vector<const MissionOptionDecl*> out;
  for (const auto& d : mission_option_declarations()) {
    if (d.group == kMeshGroup) out.push_back(&d);
  }
  return out;
}

const MissionOptionDecl* find_mission_option(std::string_view key) {
  for (const auto& d : mission_option_declarations()) {
    if (d.key == key || (!d.also.empty() && d.also == key)) return &d;
  }
  return nullptr;
}

void set_mission_option(MissionInput& input, std::string_view key, const std::string& text) {
  const MissionOptionDecl* decl = find_mission_option(key);
  if (decl == nullptr) {
    std::vector<std::string> known;
    for (const auto& d : mission_option_declarations()) known.push_back(d.key);
    throw_unknown_param("mission", std::string(key), known);
  }
  if (decl->delimiter == 0) {
    decl->set(input, text);
    return;
  }
  std::size_t begin = 0;
  for (std::size_t end; (end = text.find(decl->delimiter, begin)) != std::string::npos;
       begin = end + 1) {
    decl->set(input, text.substr(begin, end - begin));
  }
  decl->set(input, text.substr(begin));
}

grid::Cell parse_xy(const std::string& text, const std::string& option) {
  const auto comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) {
    throw ParameterError(option, fmt::format("expects X,Y (got '{}')", escape_for_message(text)));
  }
  // A cell of any grid: its coordinates lie in [0, kMaxGridSide - 1] (the grid at hand is checked
  // later, naming its size).
  constexpr int kLast = world::kMaxGridSide - 1;
  try {
    const int x = parse_integer<int>(std::string_view(text).substr(0, comma), 0, kLast);
    const int y = parse_integer<int>(std::string_view(text).substr(comma + 1), 0, kLast);
    return {x, y};
  } catch (const NumberError&) {
    throw ParameterError(
        option, fmt::format("expects X,Y with integers X and Y in [0, {}] (got '{}')", kLast,
                            escape_for_message(text)));
  }
}

world::MeshImportOptions mesh_import_options(const MeshInput& a, world::MeshImportOptions o) {
  if (a.side) o.side = world::parse_hull_side(*a.side);
  if (a.cell_size) o.cell_size = *a.cell_size;
  if (a.scale) o.scale = *a.scale;
  if (a.axes) o.axes = world::AxisMap::parse(*a.axes);
  if (a.waterline) o.waterline = a.waterline;
  if (a.min_coverage) o.min_coverage = *a.min_coverage;
  if (a.keep_largest) o.keep_largest = true;
  for (const std::string& part : a.include) {
    if (part == "transom") {
      o.include_transom = true;
    } else if (part == "bottom") {
      o.include_bottom = true;
    } else {
      throw ParameterError("include", fmt::format("expected transom, got '{}'", part));
    }
  }
  if (a.max_area_error) o.max_area_error = a.max_area_error;
  o.validate();
  return o;
}

world::MeshImport import_mesh_argument(const std::string& mesh, const MeshInput& options) {
  world::MeshImport r =
      world::is_named_mesh_hull(mesh)
          ? world::import_named_mesh_hull(mesh, mesh_import_options(options, world::dtc_options()))
          : world::import_mesh_file(mesh, mesh_import_options(options));
  for (const std::string& w : r.warnings) std::cerr << "hullinspect: warning: " << w << "\n";
  return r;
}

world::HullMask load_hull_argument(const std::string& hull, const MeshInput& mesh) {
  if (world::is_named_mesh_hull(hull) || world::is_mesh_path(hull)) {
    return std::move(import_mesh_argument(hull, mesh).hull);
  }
  // Options given with a plain mask are still checked.
  if (mesh_import_options(mesh).side == world::HullSide::both) {
    throw ParameterError("sides", "both needs a mesh hull: a mask has no 3D surface to unroll");
  }
  return world::load_hull(hull);
}

world::HullMask load_mission_hull(const MissionInput& input) {
  return load_hull_argument(input.hull, input.mesh);
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

world::CorrosionParams scenario_corrosion(const std::string& name, const OptionMap& options,
                                          int width) {
  try {
    return world::scenario(name, options).corrosion(width);
  } catch (const ParameterError& e) {
    // "perfect.p-c" is the mission option p-c.
    const auto dot = e.name().find('.');
    if (dot == std::string::npos) throw;
    throw ParameterError(e.name().substr(dot + 1), e.problem());
  }
}

void set_mission_params(const MissionInput& a, world::MissionParams& p) {
  p.uavs = a.uavs;
  p.s1 = a.s1;
  p.s2 = a.s2;
  p.theta_deg = a.theta;
  p.start_z = a.start_z;
  p.time_limit = a.time_limit;
  p.separation = a.separation;
  p.strict_separation = a.strict_separation;
  p.deconflict = !a.no_deconfliction;
  p.launch_transfer_s = a.launch_transfer;
  p.takeoff_time_s = a.takeoff_time;
  p.endurance_s = a.endurance;
  p.reserve_s = a.reserve;
  p.swap_time_s = a.swap_time;
  p.speed_m_s = a.speed;
  p.climb_speed_m_s = a.climb_speed;
}

MissionSpec build_spec(const MissionInput& a, const world::HullMask& hull) {
  if (!a.prior.empty() && !a.prior_defects.empty()) {
    throw ParameterError("prior-defects", "excludes --prior");
  }
  if (!a.truth.empty() && !a.truth_defects.empty()) {
    throw ParameterError("truth-defects", "excludes --truth");
  }
  MissionSpec spec;
  spec.algorithm = a.algorithm;
  spec.seed = a.seed;
  auto& p = spec.params;
  set_mission_params(a, p);
  if (hull.geometry()) p.cell_size_m = hull.geometry()->cell_size;
  for (const auto& s : a.starts) p.starts.push_back(parse_xy(s));
  p.no_fly = build_no_fly(a.no_fly, a.no_fly_boxes, hull);
  for (const auto& s : a.launch) p.launch_sites.push_back(parse_xy(s, "launch"));

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
  spec.corrosion = scenario_corrosion(a.scenario, scenario_options, hull.width());
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

}  // namespace hullinspect::planners
