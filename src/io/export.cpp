#include "hullinspect/io/export.hpp"

#include <fmt/format.h>

#include <cmath>

#include "export_writers.hpp"
#include "hullinspect/core/errors.hpp"

namespace hullinspect::io {

ExportFormat parse_export_format(const std::string& name) {
  for (auto f : {ExportFormat::kCsv, ExportFormat::kQgc, ExportFormat::kWpl, ExportFormat::kPath}) {
    if (to_string(f) == name) return f;
  }
  throw ParameterError("format",
                       fmt::format("'{}' is not a format (expected csv, qgc, wpl or path)", name));
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
  }
  return "?";
}

ExportPlan export_plan(const nlohmann::json& trace, const std::string& source) {
  ExportPlan plan{
      ShipFrame(ship_frame_spec(trace, source)), trace.at("plane_change_steps").get<int>(), {}, {}};
  const auto states = trace_states(trace);
  const auto same = [&plan](grid::Cell a, grid::Cell b) { return plan.frame.same_surface(a, b); };
  for (std::size_t k = 0; k < states.size(); ++k) {
    UavWaypoints u;
    u.uav = static_cast<int>(k);
    for (const auto& w : compress_trajectory(states[k], same)) {
      u.waypoints.push_back({w, plan.frame.pose(w.cell, w.z)});
    }
    plan.uavs.push_back(std::move(u));
  }
  // No-fly positions (docs/trace-format.md: rows with '#'), for the qgc geofence.
  if (auto rows = trace.find("no_fly"); rows != trace.end() && rows->is_array()) {
    for (std::size_t y = 0; y < rows->size(); ++y) {
      const auto& row = (*rows)[y];
      if (!row.is_string()) continue;
      const auto& text = row.get_ref<const std::string&>();
      for (std::size_t x = 0; x < text.size(); ++x) {
        if (text[x] == '#') plan.no_fly.push_back({static_cast<int>(x), static_cast<int>(y)});
      }
    }
  }
  return plan;
}

double cruise_speed_mps(const ExportPlan& plan) {
  return plan.frame.spec().cell_m;
}

double hold_seconds(const ExportWaypoint& w, const ExportWaypoint& previous, double speed_mps) {
  if (w.grid.action == WaypointAction::kStart) return 0.0;
  const double flight = std::hypot(w.pose.x - previous.pose.x, w.pose.y - previous.pose.y,
                                   w.pose.z - previous.pose.z) /
                        speed_mps;
  return std::max(0.0, w.grid.duration - flight);
}

namespace {

std::string uav_file_name(ExportFormat format, int uav) {
  switch (format) {
    case ExportFormat::kCsv:
      return fmt::format("uav{}.csv", uav);
    case ExportFormat::kQgc:
      return fmt::format("uav{}.plan", uav);
    case ExportFormat::kWpl:
      return fmt::format("uav{}.waypoints", uav);
    case ExportFormat::kPath:
      return fmt::format("uav{}.path.yaml", uav);
  }
  return {};
}

constexpr const char* kHullToMap = "hull_to_map.yaml";

}  // namespace

std::vector<std::string> export_file_names(ExportFormat format, int uavs, bool geo_referenced) {
  std::vector<std::string> names;
  for (int k = 0; k < uavs; ++k) names.push_back(uav_file_name(format, k));
  if (format == ExportFormat::kPath && geo_referenced) names.emplace_back(kHullToMap);
  return names;
}

std::vector<ExportFile> export_files(const ExportPlan& plan, ExportFormat format,
                                     const std::optional<GeoReference>& geo) {
  if ((format == ExportFormat::kQgc || format == ExportFormat::kWpl) && !geo) {
    throw ParameterError("origin", fmt::format("the {} format needs a geo-reference: give --origin "
                                               "LAT,LON,ALT and --heading DEG",
                                               to_string(format)));
  }
  std::vector<ExportFile> files;
  for (const auto& u : plan.uavs) {
    const std::string name = uav_file_name(format, u.uav);
    switch (format) {
      case ExportFormat::kCsv:
        files.push_back({name, detail::write_csv(plan, u, geo)});
        break;
      case ExportFormat::kQgc:
        files.push_back({name, detail::write_qgc_plan(plan, u, *geo)});
        break;
      case ExportFormat::kWpl:
        files.push_back({name, detail::write_wpl(plan, u, *geo)});
        break;
      case ExportFormat::kPath:
        files.push_back({name, detail::write_path_yaml(plan, u)});
        break;
    }
  }
  if (format == ExportFormat::kPath && geo) {
    files.push_back({kHullToMap, detail::write_hull_to_map_yaml(*geo)});
  }
  return files;
}

}  // namespace hullinspect::io
