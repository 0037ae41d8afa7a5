#include "hullinspect/io/export.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "export_writers.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/io/simplify.hpp"

namespace hullinspect::io {

namespace {

constexpr std::array<ExportFormat, 7> kFormats = {
    ExportFormat::kCsv,    ExportFormat::kQgc,    ExportFormat::kWpl, ExportFormat::kPath,
    ExportFormat::kLitchi, ExportFormat::kDjiKmz, ExportFormat::kKml};

constexpr std::array<std::string_view, 5> kDroneNames = {"m350", "m300", "m30", "m30t", "m3e"};

}  // namespace

ExportFormat parse_export_format(const std::string& name) {
  for (auto f : kFormats) {
    if (to_string(f) == name) return f;
  }
  throw ParameterError("format", fmt::format("'{}' is not a format (expected csv, qgc, wpl, path, "
                                             "litchi, dji-kmz, kml or all)",
                                             name));
}

std::string_view to_string(ExportFormat format) {
  switch (format) {
    case ExportFormat::kCsv:
      return "csv";
    case ExportFormat::kQgc:
      return "qgc";
    case ExportFormat::kWpl:
      return "wpl";
    case ExportFormat::kPath:
      return "path";
    case ExportFormat::kLitchi:
      return "litchi";
    case ExportFormat::kDjiKmz:
      return "dji-kmz";
    case ExportFormat::kKml:
      return "kml";
  }
  return "?";
}

std::vector<ExportFormat> parse_export_formats(const std::vector<std::string>& names) {
  std::vector<ExportFormat> formats;
  const auto add = [&formats](ExportFormat f) {
    if (std::find(formats.begin(), formats.end(), f) == formats.end()) formats.push_back(f);
  };
  for (const auto& name : names) {
    if (name == "all") {
      for (auto f : kFormats) add(f);
    } else {
      add(parse_export_format(name));
    }
  }
  return formats;
}

bool drops_no_fly(ExportFormat format) {
  return format == ExportFormat::kQgc || format == ExportFormat::kWpl ||
         format == ExportFormat::kLitchi || format == ExportFormat::kDjiKmz;
}

bool needs_geo_reference(ExportFormat format) {
  return format != ExportFormat::kCsv && format != ExportFormat::kPath;
}

DjiDrone parse_dji_drone(const std::string& name) {
  for (std::size_t i = 0; i < kDroneNames.size(); ++i) {
    if (kDroneNames[i] == name) return static_cast<DjiDrone>(i);
  }
  throw ParameterError("drone", fmt::format("'{}' is not a DJI aircraft (expected m350, m300, "
                                            "m30, m30t or m3e)",
                                            name));
}

int default_waypoint_cap(ExportFormat format) {
  switch (format) {
    case ExportFormat::kLitchi:
      return 99;
    case ExportFormat::kDjiKmz:
      return 200;
    default:
      return 0;
  }
}

bool ExportPlan::is_hull(grid::Cell c) const {
  if (c.y < 0 || static_cast<std::size_t>(c.y) >= hull_rows.size()) return false;
  const auto& row = hull_rows[static_cast<std::size_t>(c.y)];
  return c.x >= 0 && static_cast<std::size_t>(c.x) < row.size() &&
         row[static_cast<std::size_t>(c.x)] != '.';
}

namespace {
std::vector<grid::Cell> marked_cells(const nlohmann::json& rows, char mark) {
  std::vector<grid::Cell> cells;
  if (!rows.is_array()) return cells;
  for (std::size_t y = 0; y < rows.size(); ++y) {
    if (!rows[y].is_string()) continue;
    const auto& text = rows[y].get_ref<const std::string&>();
    for (std::size_t x = 0; x < text.size(); ++x) {
      if (text[x] == mark) cells.push_back({static_cast<int>(x), static_cast<int>(y)});
    }
  }
  return cells;
}
}  // namespace

ExportPlan export_plan(const nlohmann::json& trace, const std::string& source) {
  ExportPlan plan{ShipFrame(ship_frame_spec(trace, source)),
                  trace.at("plane_change_steps").get<int>(),
                  trace.at("grid").at("width").get<int>(),
                  trace.at("grid").at("height").get<int>(),
                  {},
                  {},
                  {},
                  {}};
  if (auto step = trace.find("step_seconds"); step != trace.end()) {
    plan.step_seconds = step->get<double>();
  }
  plan.states = trace_states(trace);
  const auto same = [&plan](grid::Cell a, grid::Cell b) { return plan.frame.same_surface(a, b); };
  for (const auto& uav : plan.states) {
    std::vector<ExportWaypoint> waypoints;
    for (const auto& w : compress_trajectory(uav, same)) {
      waypoints.push_back({w, plan.frame.pose(w.cell, w.z)});
    }
    plan.uavs.push_back(std::move(waypoints));
  }
  // No-fly positions (docs/trace-format.md: rows with '#').
  if (auto rows = trace.find("no_fly"); rows != trace.end()) plan.no_fly = marked_cells(*rows, '#');
  if (auto rows = trace.find("truth"); rows != trace.end() && rows->is_array()) {
    for (const auto& row : *rows)
      plan.hull_rows.push_back(row.is_string() ? row.get<std::string>() : "");
  }
  // The mission's launch sites (docs/trace-format.md, checked by read_trace).
  if (auto launch = trace.find("launch"); launch != trace.end() && launch->is_object()) {
    for (const auto& xy : launch->at("sites")) {
      plan.launch_sites.push_back({xy.at(0).get<int>(), xy.at(1).get<int>()});
    }
    plan.site_of = launch->at("site_of").get<std::vector<int>>();
  }
  plan.battery_limited = trace.contains("battery");
  if (auto result = trace.find("result");
      result != trace.end() && result->value("complete", false)) {
    const auto& known = trace.at("series").at("known");
    for (std::size_t t = 0; t < known.size(); ++t) {
      if (known[t] == known.back()) {
        plan.homing_frame = static_cast<int>(t);
        break;
      }
    }
  }
  return plan;
}

double cruise_speed_mps(const ExportPlan& plan) {
  return plan.frame.spec().cell_m / plan.step_seconds;
}

double photo_distance_m(const ExportPlan& plan) {
  return plan.frame.spec().cell_m;
}

double hold_seconds(const ExportPlan& plan, const ExportWaypoint& w,
                    const ExportWaypoint& previous) {
  if (w.grid.action == WaypointAction::kStart) return 0.0;
  const double flight = std::hypot(w.pose.x - previous.pose.x, w.pose.y - previous.pose.y,
                                   w.pose.z - previous.pose.z) /
                        cruise_speed_mps(plan);
  return std::max(0.0, plan.seconds(w.grid.duration) - flight);
}

namespace {

std::string_view extension(ExportFormat format) {
  switch (format) {
    case ExportFormat::kCsv:
      return "csv";
    case ExportFormat::kQgc:
      return "plan";
    case ExportFormat::kWpl:
      return "waypoints";
    case ExportFormat::kPath:
      return "path.yaml";
    case ExportFormat::kLitchi:
      return "litchi.csv";
    case ExportFormat::kDjiKmz:
      return "kmz";
    case ExportFormat::kKml:
      return "kml";
  }
  return {};
}

constexpr const char* kHullToMap = "hull_to_map.yaml";
constexpr const char* kKmlPreview = "mission.kml";

}  // namespace

std::string mission_file_name(ExportFormat format, const MissionPart& part) {
  const auto& s = *part.sortie;
  const std::string stem =
      s.flown ? fmt::format("uav{}_sortie{}", s.uav, s.number) : fmt::format("uav{}", s.uav);
  if (part.parts == 1) return fmt::format("{}.{}", stem, extension(format));
  return fmt::format("{}-part{}.{}", stem, part.part, extension(format));
}

std::string_view to_string(Firmware firmware) {
  return firmware == Firmware::kArduPilot ? "ardupilot" : "px4";
}

namespace {
// The firmwares a qgc or wpl file is written for (ExportSettings::firmwares).
std::vector<Firmware> firmwares_of(ExportFormat format, const ExportSettings& settings) {
  if ((format != ExportFormat::kQgc && format != ExportFormat::kWpl) ||
      settings.firmwares.size() < 2) {
    return {settings.firmware};
  }
  return settings.firmwares;
}
}  // namespace

std::vector<std::string> mission_file_names(ExportFormat format, const MissionPart& part,
                                            const ExportSettings& settings) {
  const auto name = mission_file_name(format, part);
  const auto firmwares = firmwares_of(format, settings);
  if (firmwares.size() < 2) return {name};
  std::vector<std::string> names;
  const auto dot = name.rfind('.');
  for (const auto f : firmwares) {
    names.push_back(fmt::format("{}.{}{}", name.substr(0, dot), to_string(f), name.substr(dot)));
  }
  return names;
}

std::vector<std::string> export_file_names(ExportFormat format, int uavs, bool geo_referenced) {
  std::vector<std::string> names;
  if (format == ExportFormat::kKml) return {kKmlPreview};
  for (int k = 0; k < uavs; ++k) names.push_back(fmt::format("uav{}.{}", k, extension(format)));
  if (format == ExportFormat::kPath && geo_referenced) names.emplace_back(kHullToMap);
  return names;
}

std::vector<ExportFile> export_files(const ExportPlan& plan, ExportFormat format,
                                     const std::optional<GeoReference>& geo,
                                     const ExportSettings& settings) {
  if (needs_geo_reference(format) && !geo) {
    throw ParameterError("origin", fmt::format("the {} format needs a geo-reference: give --origin "
                                               "LAT,LON,ALT and --heading DEG (or --geo FILE)",
                                               to_string(format)));
  }
  auto sorties =
      plan_sorties(plan, settings.launch_sites, settings.flown_sorties, settings.launch_height_m);
  if (settings.simplify_m > 0) {
    for (auto& s : sorties) simplify_sortie(plan, s, settings.simplify_m);
  }
  std::vector<ExportFile> files;
  if (format == ExportFormat::kKml) {
    files.push_back({kKmlPreview, detail::write_kml(plan, sorties, *geo)});
    return files;
  }
  const int cap =
      settings.max_waypoints > 0 ? settings.max_waypoints : default_waypoint_cap(format);
  const auto firmwares = firmwares_of(format, settings);
  for (const auto& sortie : sorties) {
    for (const auto& part : split_sortie(sortie, cap)) {
      const auto names = mission_file_names(format, part, settings);
      const std::string& name = names.front();
      switch (format) {
        case ExportFormat::kCsv:
          files.push_back({name, detail::write_csv(plan, part, geo)});
          break;
        case ExportFormat::kQgc:
        case ExportFormat::kWpl:
          for (std::size_t i = 0; i < firmwares.size(); ++i) {
            auto one = settings;
            one.firmware = firmwares[i];
            files.push_back({names[i], format == ExportFormat::kQgc
                                           ? detail::write_qgc_plan(plan, part, *geo, one)
                                           : detail::write_wpl(plan, part, *geo, one)});
          }
          break;
        case ExportFormat::kPath:
          files.push_back({name, detail::write_path_yaml(plan, part)});
          break;
        case ExportFormat::kLitchi:
          files.push_back({name, detail::write_litchi(plan, part, *geo)});
          break;
        case ExportFormat::kDjiKmz:
          files.push_back({name, detail::write_dji_kmz(plan, part, *geo, settings)});
          break;
        case ExportFormat::kKml:
          break;
      }
    }
  }
  if (format == ExportFormat::kPath && geo) {
    files.push_back({kHullToMap, detail::write_hull_to_map_yaml(*geo)});
  }
  return files;
}

}  // namespace hullinspect::io
