#include "export_options.hpp"

#include "number_options.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include <limits>
#include <set>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"
#include "hullinspect/files/bounded_read.hpp"
#include "hullinspect/io/geo_survey.hpp"
#include "hullinspect/planners/mission_input.hpp"
#include "hullinspect/world/battery.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/ship_frame_bounds.hpp"

#include <algorithm>

namespace hullinspect::cli {

namespace fs = std::filesystem;

namespace {
// The geoid departs from the WGS-84 ellipsoid by −106 m to +85 m (EGM2008): a wider value is not
// a geoid height.
constexpr double kMaxGeoidHeightM = 120;
}  // namespace

void add_export_options(CLI::App& cmd, ExportArgs& a, const std::string& dir_option,
                        bool launch_option) {
  cmd.add_option(dir_option, a.dir,
                 "Write each UAV's waypoints into DIR (created if missing; see docs/export.md)")
      ->type_name("DIR");
  cmd.add_option("--format", a.formats,
                 "Waypoint format, repeatable: csv, qgc (QGroundControl .plan), wpl (QGC WPL 110), "
                 "path (nav_msgs/Path YAML), litchi (Litchi CSV mission), dji-kmz (DJI WPML "
                 "wayline), kml (Google Earth preview), or all")
      ->default_str(std::string(io::to_string(kDefaultExportFormat)))
      ->allow_extra_args(false)
      ->type_name("FORMAT");
  cmd.add_option(
         "--origin", a.origin,
         "Geo-reference: WGS-84 latitude, longitude (degrees) and ellipsoidal height (m) of "
         "the ship-frame origin")
      ->type_name("LAT,LON,ALT");
  cmd.add_option("--heading", a.heading,
                 "Geo-reference: ship heading, degrees clockwise from north")
      ->check(
          real_in(-io::kMaxHeadingDeg,
                  io::kMaxHeadingDeg))  // a custom type name hides it from require_exact_numbers()
      ->type_name("DEG");
  cmd.add_option("--geo", a.geo_file,
                 "Geo-reference from a YAML file: origin: [LAT, LON, ALT], heading: DEG")
      ->type_name("FILE");
  if (launch_option) {
    cmd.add_option("--launch", a.launch,
                   "Launch site at grid position X,Y (a non-hull or edge cell), repeatable; each "
                   "UAV flies one sortie from the nearest site (default: it takes off below its "
                   "start)")
        ->type_name("X,Y");
  }
  cmd.add_option("--max-waypoints", a.max_waypoints,
                 "Split a sortie into mission files of at most N waypoints (default: litchi 99, "
                 "dji-kmz 200, others no cap)")
      ->check(integer_text_in(io::kMinWaypointCap, std::numeric_limits<int>::max()))
      ->type_name("N");
  cmd.add_option("--simplify", a.simplify,
                 "Merge legs whose waypoints lie within TOL metres of a straight line, keeping "
                 "coverage (refused, naming the first cell lost, if it would not)")
      ->check(real_in(0.0, 1e3))
      ->type_name("TOL_M");
  cmd.add_option("--launch-height", a.launch_height,
                 "Height Z (m, ship frame) of the ground a sortie takes off from and lands on "
                 "below its launch site (default: the grid's bottom edge)")
      ->check(real_in(-world::kMaxShipFrameM, world::kMaxShipFrameM))
      ->type_name("Z_M");
  cmd.add_option("--geoid-height", a.geoid_height,
                 "The geoid's height above the WGS-84 ellipsoid at the ship (m): qgc and wpl write "
                 "their home altitude above mean sea level (default: ellipsoidal, with a warning)")
      ->check(real_in(-kMaxGeoidHeightM, kMaxGeoidHeightM))
      ->type_name("N_M");
  cmd.add_option("--firmware", a.firmwares,
                 "Flight controller of qgc/wpl missions, repeatable: px4, ardupilot (default px4; "
                 "with both, each file's name says which)")
      ->allow_extra_args(false)
      ->type_name("FIRMWARE");
  cmd.add_option("--finish", a.finish,
                 "After the last waypoint: land (at the home point) or rtl (return to launch)")
      ->capture_default_str();
  cmd.add_option("--drone", a.drone, "DJI aircraft of dji-kmz files: m350, m300, m30, m30t, m3e")
      ->capture_default_str();
  cmd.add_flag("--force", a.force,
               "Write into the directory even if it already holds files (files of the same names "
               "are replaced, others are left as they are)");
}

namespace {

// A geo-reference file is a few lines; anything larger is not one.
constexpr std::size_t kMaxGeoFileBytes = std::size_t{1} << 20;

// yaml-cpp keeps the first of two equal keys silently; a file that says `heading` twice is
// ambiguous, so it is refused.
void refuse_duplicate_keys(const YAML::Node& map, const std::string& path) {
  std::set<std::string> seen;
  for (const auto& entry : map) {
    const std::string key = entry.first.Scalar();
    if (!seen.insert(key).second) {
      throw InputError(path, entry.first.Mark().line + 1,
                       fmt::format("duplicate key '{}'", escape_for_message(key, 200)));
    }
  }
}

// A number of a geo-reference file, with the number rules and ranges of --origin and --heading
// (core/numbers.hpp).
double yaml_number(const YAML::Node& node, const std::string& field, double min, double max,
                   const std::string& path) {
  const int line = node.Mark().line + 1;
  if (!node.IsScalar()) throw InputError(path, line, field + ": expected a number");
  try {
    return parse_real(node.Scalar(), min, max);
  } catch (const NumberError& e) {
    throw InputError(path, line, field + ": " + e.what());
  }
}

// [LAT, LON, ALT] (the caller checked the sequence's size).
io::GeoPoint geo_point(const YAML::Node& node, const std::string& field, const std::string& path) {
  return {
      yaml_number(node[0], field + "[0] (latitude)", -io::kMaxLatitudeDeg, io::kMaxLatitudeDeg,
                  path),
      yaml_number(node[1], field + "[1] (longitude)", -io::kMaxLongitudeDeg, io::kMaxLongitudeDeg,
                  path),
      yaml_number(node[2], field + "[2] (height)", io::kMinOriginAltM, io::kMaxOriginAltM, path)};
}

// The geo-reference of two surveyed points whose ship-frame coordinates are all known.
io::GeoReference survey_reference(const std::array<io::SurveyedPoint, 2>& points,
                                  double tolerance_m, const std::string& path, int line) {
  try {
    return io::geo_from_survey(points[0], points[1], tolerance_m);
  } catch (const ParameterError& e) {
    throw InputError(path, line, "survey: " + e.problem());
  }
}

// survey: [{ship: [X, Y, Z] or [X, Z], at: [LAT, LON, ALT]} or {cell: [COL, ROW], at: …}, {…}]
// and an optional tolerance: M (docs/export.md, "Two surveyed points").
CellSurvey survey_yaml(const YAML::Node& doc, const std::string& path) {
  for (const auto& entry : doc) {
    const std::string key = entry.first.Scalar();
    if (key != "survey" && key != "tolerance") {
      throw InputError(path, entry.first.Mark().line + 1,
                       fmt::format("{}: not with survey (a survey gives the origin and the "
                                   "heading; known: survey, tolerance)",
                                   escape_for_message(key, 200)));
    }
  }
  const auto survey = doc["survey"];
  constexpr const char* kPointForm =
      "{ship: [X, Y, Z], at: [LAT, LON, ALT]} or {cell: [COL, ROW], at: [LAT, LON, ALT]}";
  if (!survey.IsSequence() || survey.size() != 2) {
    throw InputError(path, survey.Mark().line + 1,
                     fmt::format("survey: expected two points, each {}", kPointForm));
  }
  CellSurvey out;
  out.path = path;
  out.line = survey.Mark().line + 1;
  for (std::size_t i = 0; i < 2; ++i) {
    const auto node = survey[i];
    const std::string field = fmt::format("survey[{}]", i);
    const int line = node.Mark().line + 1;
    out.lines[i] = line;
    if (!node.IsMap() || !node["at"] || (!node["ship"] == !node["cell"])) {
      throw InputError(path, line, fmt::format("{}: expected {}", field, kPointForm));
    }
    refuse_duplicate_keys(node, path);
    for (const auto& entry : node) {
      const std::string key = entry.first.Scalar();
      if (key != "ship" && key != "cell" && key != "at") {
        throw InputError(path, entry.first.Mark().line + 1,
                         fmt::format("{}.{}: unknown key (known: ship or cell, at)", field,
                                     escape_for_message(key, 200)));
      }
    }
    auto& p = out.points[i];
    if (const auto cell = node["cell"]) {
      if (!cell.IsSequence() || cell.size() != 2) {
        throw InputError(path, cell.Mark().line + 1,
                         field + ".cell: expected [COL, ROW], the hull grid's column and row");
      }
      int v[2] = {0, 0};
      for (std::size_t k = 0; k < 2; ++k) {
        const char* axis = k == 0 ? "COL" : "ROW";
        if (!cell[k].IsScalar()) {
          throw InputError(path, cell.Mark().line + 1,
                           fmt::format("{}.cell ({}): expected an integer", field, axis));
        }
        try {
          v[k] = parse_integer<int>(cell[k].Scalar(), 0, world::kMaxGridSide - 1);
        } catch (const NumberError& e) {
          throw InputError(path, cell.Mark().line + 1,
                           fmt::format("{}.cell ({}): {}", field, axis, e.what()));
        }
      }
      out.cells[i] = grid::Cell{v[0], v[1]};
    } else {
      const auto ship = node["ship"];
      if (!ship.IsSequence() || (ship.size() != 2 && ship.size() != 3)) {
        throw InputError(path, ship.Mark().line + 1,
                         field + ".ship: expected [X, Y, Z] or [X, Z] in metres of the ship frame");
      }
      const auto metres = [&](std::size_t k, const char* axis) {
        return yaml_number(ship[k], fmt::format("{}.ship ({})", field, axis),
                           -world::kMaxShipFrameM, world::kMaxShipFrameM, path);
      };
      p.x = metres(0, "X");
      p.y = ship.size() == 3 ? metres(1, "Y") : 0.0;
      p.z = metres(ship.size() - 1, "Z");
    }
    const auto at = node["at"];
    if (!at.IsSequence() || at.size() != 3) {
      throw InputError(path, at.Mark().line + 1, field + ".at: expected [LAT, LON, ALT]");
    }
    p.at = geo_point(at, field + ".at", path);
  }
  if (doc["tolerance"])
    out.tolerance_m = yaml_number(doc["tolerance"], "tolerance", 0.0, 1e3, path);
  return out;
}

// The keys of a --geo file's two forms.
constexpr const char* kGeoKeys = "origin and heading, or survey and tolerance";

// The --geo file's geo-reference, or its survey when a surveyed point is a grid cell (the
// reference then waits for the mission's frame).
void geo_from_yaml(const std::string& path, ExportRequest& request) {
  // Read like every input (bounded, regular files only, registered against the outputs).
  const std::string text = io::read_file(path, kMaxGeoFileBytes, "the geo-reference file");
  YAML::Node doc;
  try {
    doc = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(path, e.mark.line + 1, "not YAML: " + escape_for_message(e.msg, 200));
  }
  if (!doc.IsMap()) {
    throw InputError(path, 0, "expected a YAML mapping with origin: [LAT, LON, ALT] and heading");
  }
  refuse_duplicate_keys(doc, path);
  if (doc["survey"]) {
    auto survey = survey_yaml(doc, path);
    if (survey.cells[0] || survey.cells[1]) {
      request.cell_survey = std::move(survey);
    } else {
      request.geo = survey_reference(survey.points, survey.tolerance_m, path, survey.line);
    }
    return;
  }
  for (const auto& entry : doc) {
    const std::string key = entry.first.Scalar();
    if (key != "origin" && key != "heading") {
      throw InputError(
          path, entry.first.Mark().line + 1,
          fmt::format("{}: unknown key (expected {})", escape_for_message(key, 200), kGeoKeys));
    }
  }
  const auto origin = doc["origin"];
  if (!origin || !origin.IsSequence() || origin.size() != 3) {
    throw InputError(path, origin ? origin.Mark().line + 1 : 0, "origin: expected [LAT, LON, ALT]");
  }
  const auto heading = doc["heading"];
  if (!heading || !heading.IsScalar()) {
    throw InputError(path, 0, "heading: expected degrees clockwise from north");
  }
  const io::GeoPoint point = geo_point(origin, "origin", path);
  request.geo.emplace(
      point, yaml_number(heading, "heading", -io::kMaxHeadingDeg, io::kMaxHeadingDeg, path));
}

// The geo-reference of an export: the request's, or its cell survey's on the plan's frame.
std::optional<io::GeoReference> export_geo(const ExportRequest& request,
                                           const io::ExportPlan& plan) {
  if (!request.cell_survey) return request.geo;
  const auto& survey = *request.cell_survey;
  auto points = survey.points;
  for (std::size_t i = 0; i < 2; ++i) {
    if (!survey.cells[i]) continue;
    const grid::Cell c = *survey.cells[i];
    if (!plan.is_hull(c)) {
      throw InputError(survey.path, survey.lines[i],
                       fmt::format("survey[{}].cell: ({}, {}) is not a hull cell of the mission's "
                                   "{} × {} grid (a surveyed point lies on the hull)",
                                   i, c.x, c.y, plan.width, plan.height));
    }
    const auto s = plan.frame.surface_point(c);
    points[i].x = s[0];
    points[i].y = s[1];
    points[i].z = s[2];
  }
  return survey_reference(points, survey.tolerance_m, survey.path, survey.line);
}

}  // namespace

std::optional<ExportRequest> resolve_export(const ExportArgs& a, const std::string& dir_option) {
  const std::string name = dir_option.substr(2);
  if (a.dir.empty()) {
    const ExportArgs defaults;
    for (const auto& [set, option] :
         {std::pair{!a.formats.empty(), "format"}, std::pair{!a.origin.empty(), "origin"},
          std::pair{a.heading.has_value(), "heading"}, std::pair{!a.geo_file.empty(), "geo"},
          std::pair{!a.launch.empty(), "launch"},
          std::pair{a.max_waypoints.has_value(), "max-waypoints"},
          std::pair{a.simplify.has_value(), "simplify"},
          std::pair{a.launch_height.has_value(), "launch-height"},
          std::pair{a.geoid_height.has_value(), "geoid-height"},
          std::pair{!a.firmwares.empty(), "firmware"},
          std::pair{a.finish != defaults.finish, "finish"},
          std::pair{a.drone != defaults.drone, "drone"}, std::pair{a.force, "force"}}) {
      if (set)
        throw ParameterError(option, fmt::format("has no effect without {} DIR", dir_option));
    }
    return std::nullopt;
  }
  ExportRequest r;
  r.dir = a.dir;
  if (!a.formats.empty()) r.formats = io::parse_export_formats(a.formats);
  for (const auto& firmware : a.firmwares) {
    io::Firmware f = io::Firmware::kPx4;
    if (firmware == "ardupilot") {
      f = io::Firmware::kArduPilot;
    } else if (firmware != "px4") {
      throw ParameterError("firmware", fmt::format("'{}' is not a firmware (expected px4 or "
                                                   "ardupilot)",
                                                   escape_for_message(firmware, 200)));
    }
    auto& list = r.settings.firmwares;
    if (std::find(list.begin(), list.end(), f) == list.end()) list.push_back(f);
  }
  if (!r.settings.firmwares.empty()) r.settings.firmware = r.settings.firmwares.front();
  if (a.finish == "rtl") {
    r.settings.finish = io::FinishAction::kRtl;
  } else if (a.finish != "land") {
    throw ParameterError("finish",
                         fmt::format("'{}' is not a finish (expected land or rtl)", a.finish));
  }
  r.settings.drone = io::parse_dji_drone(a.drone);
  for (const auto& text : a.launch)
    r.settings.launch_sites.push_back(planners::parse_xy(text, "launch"));
  if (a.max_waypoints) {
    if (*a.max_waypoints < io::kMinWaypointCap) {
      throw ParameterError("max-waypoints",
                           fmt::format("{} is below the {} waypoints a mission file needs (the "
                                       "point it starts from and one to fly to)",
                                       *a.max_waypoints, io::kMinWaypointCap));
    }
    r.settings.max_waypoints = *a.max_waypoints;
  }
  if (a.simplify) r.settings.simplify_m = *a.simplify;
  r.settings.launch_height_m = a.launch_height;
  r.settings.geoid_height_m = a.geoid_height;
  if (!a.geo_file.empty()) {
    if (!a.origin.empty() || a.heading) {
      throw ParameterError("geo", "give either --geo FILE or --origin and --heading, not both");
    }
    geo_from_yaml(a.geo_file, r);
  } else if (!a.origin.empty() || a.heading) {
    if (a.origin.empty())
      throw ParameterError("origin", "--heading needs --origin LAT,LON,ALT too");
    if (!a.heading) throw ParameterError("heading", "--origin needs --heading DEG too");
    r.geo = io::GeoReference(io::parse_geo_origin(a.origin), *a.heading);
  }
  for (const auto f : r.formats) {
    if (io::needs_geo_reference(f) && !r.geo && !r.cell_survey) {
      throw ParameterError("origin", fmt::format("the {} format needs a geo-reference: give "
                                                 "--origin LAT,LON,ALT and --heading DEG (or --geo "
                                                 "FILE)",
                                                 io::to_string(f)));
    }
  }
  r.option = name;
  r.geo_file = a.geo_file;
  r.force = a.force;
  return r;
}

void take_mission_sorties(ExportRequest& request, const planners::MissionSpec& spec,
                          const sim::MissionResult& result) {
  if (!world::battery_steps(spec.params).limited) return;
  auto& flown = request.settings.flown_sorties;
  flown.clear();
  for (const auto& u : result.uavs) {
    auto& sorties = flown.emplace_back();
    for (const auto& s : u.sorties) sorties.push_back({s.takeoff, s.landing, s.site});
  }
}

void declare_export_dir(io::OutputSet& outputs, const ExportRequest& request) {
  outputs.add_input(request.geo_file, "geo");
  // A new or empty directory, unless --force: files of an earlier export with more UAVs would
  // otherwise stay beside the new ones and read as part of it.
  outputs.add_output_dir(request.dir, request.option, !request.force);
}

namespace {
std::vector<std::string> declared_names(const ExportRequest& request, int uavs) {
  std::vector<std::string> names;
  for (const auto f : request.formats) {
    for (auto& n : io::export_file_names(f, uavs, request.geo || request.cell_survey)) {
      names.push_back(std::move(n));
    }
  }
  return names;
}
}  // namespace

void declare_export_files(io::OutputSet& outputs, const ExportRequest& request, int uavs) {
  for (const auto& name : declared_names(request, uavs)) {
    outputs.add_output(request.dir / name, request.option);
  }
}

namespace {
// The settings of an export of `plan`: a mission with launch sites flies from its own sites (its
// trace's flights start and end there), and a battery-limited one is cut at the sorties its trace
// records (plan and run pass their result's, which are the same).
io::ExportSettings trace_settings(const ExportRequest& request, const io::ExportPlan& plan) {
  auto settings = request.settings;
  if (!plan.launch_sites.empty()) {
    if (!settings.launch_sites.empty() && settings.launch_sites != plan.launch_sites) {
      std::vector<std::string> sites;
      for (const auto& c : plan.launch_sites) sites.push_back(fmt::format("{},{}", c.x, c.y));
      throw ParameterError("launch",
                           fmt::format("the trace's mission has its own launch sites ({}): "
                                       "its flights start and end there",
                                       fmt::join(sites, " ")));
    }
    settings.launch_sites = plan.launch_sites;
  }
  if (plan.battery_limited && settings.flown_sorties.empty()) {
    settings.flown_sorties = io::recorded_sorties(plan);
  }
  return settings;
}
}  // namespace

ExportWritten write_export(const nlohmann::json& trace, const std::string& source,
                           const ExportRequest& request, io::OutputSet& outputs) {
  const auto plan = io::export_plan(trace, source);
  const auto declared = declared_names(request, static_cast<int>(plan.uavs.size()));
  ExportWritten written;
  written.geo = export_geo(request, plan);
  const auto settings = trace_settings(request, plan);
  std::vector<io::ExportFile> files;
  std::vector<std::string> dropped;
  for (const auto f : request.formats) {
    for (auto& file : io::export_files(plan, f, written.geo, settings)) {
      files.push_back(std::move(file));
    }
    if (!plan.no_fly.empty() && io::drops_no_fly(f)) dropped.emplace_back(io::to_string(f));
  }
  if (!dropped.empty()) {
    written.notes.push_back(fmt::format(
        "the no-fly positions are not in the {} files: {} no vertical obstacle, and a horizontal "
        "fence would also forbid the legal flight past them (the kml preview draws them)",
        fmt::join(dropped, ", "), dropped.size() == 1 ? "the format has" : "these formats have"));
  }
  // Part files of split sorties are known only now: declare and check them before writing.
  bool added = false;
  for (const auto& f : files) {
    if (std::find(declared.begin(), declared.end(), f.name) == declared.end()) {
      outputs.add_output(request.dir / f.name, request.option);
      added = true;
    }
  }
  if (added) outputs.check();
  for (const auto& f : files) {
    outputs.write(request.dir / f.name, f.content);
    written.names.push_back(f.name);
  }
  return written;
}

std::string format_list(const ExportRequest& request) {
  std::vector<std::string> names;
  for (const auto f : request.formats) names.emplace_back(io::to_string(f));
  if (names.size() == 1) return names.front();
  const std::string last = names.back();
  names.pop_back();
  return fmt::format("{} and {}", fmt::join(names, ", "), last);
}

}  // namespace hullinspect::cli
