#include "hullinspect/io/preflight_report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <cmath>

#include "hullinspect/io/preflight_separation.hpp"
#include "hullinspect/io/simplify.hpp"

namespace hullinspect::io {

namespace {

constexpr std::array<const char*, 8> kColours = {"#e41a1c", "#377eb8", "#4daf4a", "#984ea3",
                                                 "#ff7f00", "#a65628", "#f781bf", "#999999"};

std::vector<Sortie> exported_sorties(const ExportPlan& plan, const ExportSettings& settings) {
  auto sorties = plan_sorties(plan, settings.launch_sites);
  if (settings.simplify_m > 0) {
    for (auto& s : sorties) simplify_sortie(plan, s, settings.simplify_m);
  }
  return sorties;
}

double length(const ShipPose& a, const ShipPose& b) {
  return std::hypot(b.x - a.x, b.y - a.y, b.z - a.z);
}

int count_rows(const nlohmann::json& rows, char mark) {
  int n = 0;
  if (!rows.is_array()) return 0;
  for (const auto& r : rows) {
    if (!r.is_string()) continue;
    for (char c : r.get<std::string>()) n += c == mark;
  }
  return n;
}

}  // namespace

nlohmann::json preflight_report(const nlohmann::json& trace, const ExportPlan& plan,
                                const std::vector<ExportFormat>& formats,
                                const ExportSettings& settings,
                                const std::optional<GeoReference>& geo) {
  using nlohmann::json;
  const auto sorties = exported_sorties(plan, settings);
  const double speed = cruise_speed_mps(plan);
  json report;
  report["format"] = "hullinspect-preflight";
  report["version"] = 1;
  json rows = json::array();
  json warnings = json::array();
  std::vector<std::vector<char>> seen(static_cast<std::size_t>(plan.height),
                                      std::vector<char>(static_cast<std::size_t>(plan.width), 0));
  for (const auto& s : sorties) {
    mark_seen(plan, s.waypoints, seen);
    // Distance: the climb from home, every leg, the descent home; time: at the cruise speed plus
    // every hold.
    double distance = s.waypoints.empty() ? 0.0 : length(s.home, s.waypoints.front().pose);
    double holds = 0;
    for (std::size_t i = 1; i < s.waypoints.size(); ++i) {
      distance += length(s.waypoints[i - 1].pose, s.waypoints[i].pose);
      holds += hold_seconds(plan, s.waypoints[i], s.waypoints[i - 1]);
    }
    if (!s.waypoints.empty()) distance += length(s.waypoints.back().pose, s.home);
    json files = json::object();
    for (const auto f : formats) {
      if (f == ExportFormat::kKml) continue;
      const int cap = settings.max_waypoints > 0 ? settings.max_waypoints : default_waypoint_cap(f);
      const auto parts = static_cast<int>(split_sortie(s, cap).size());
      files[std::string(to_string(f))] = parts;
      if (parts > 1) {
        warnings.push_back(
            fmt::format("UAV {} sortie {}: {} waypoints exceed the {} cap of {}: "
                        "{} files, flown one after the other",
                        s.uav, s.number, s.waypoints.size(), to_string(f), cap, parts));
      }
    }
    json row = {{"uav", s.uav},
                {"sortie", s.number},
                {"launch_site", {s.site.x, s.site.y}},
                {"launch_site_given", s.given_site},
                {"waypoints", s.waypoints.size()},
                {"distance_m", std::round(distance * 100) / 100},
                {"flight_time_s", std::round((distance / speed + holds) * 10) / 10},
                // The battery's margin at landing: left empty until the mission models an
                // endurance (never a made-up number).
                {"battery_margin_s", nullptr},
                {"files", files}};
    if (geo) {
      const auto h = geo->to_wgs84(s.home.x, s.home.y, s.home.z);
      row["home"] = {std::round(h.lat * 1e8) / 1e8, std::round(h.lon * 1e8) / 1e8};
    }
    rows.push_back(row);
  }
  report["sorties"] = rows;
  // Hull cells no footprint of the exported flights contains.
  json unseen = json::array();
  int hull_cells = 0;
  for (int y = 0; y < plan.height; ++y) {
    for (int x = 0; x < plan.width; ++x) {
      hull_cells += plan.is_hull({x, y});
      if (plan.is_hull({x, y}) && !seen[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)]) {
        unseen.push_back({x, y});
      }
    }
  }
  const auto unreachable = trace.find("unreachable");
  report["cells"] = {
      {"hull", hull_cells},
      {"unreachable", unreachable != trace.end() ? count_rows(*unreachable, 'x') : 0},
      {"undetectable_from_z2", unreachable != trace.end() ? count_rows(*unreachable, 'd') : 0},
      {"unseen", unseen.size()},
      {"unseen_cells", unseen}};
  if (!plan.no_fly.empty()) {
    std::vector<std::string> dropped;
    for (const auto f : formats) {
      if (drops_no_fly(f)) dropped.emplace_back(to_string(f));
    }
    if (!dropped.empty()) {
      warnings.push_back(
          fmt::format("{} no-fly positions are not in the {} files (no vertical "
                      "obstacle in these formats); check the route against the kml "
                      "preview",
                      plan.no_fly.size(), fmt::join(dropped, ", ")));
    }
  }
  std::vector<std::string> separation_warnings;
  report["separation"] = preflight_separation(trace, plan, separation_warnings);
  for (auto& w : separation_warnings) warnings.push_back(std::move(w));
  const auto& result = trace.at("result");
  if (!result.value("complete", true)) {
    warnings.push_back(
        "the plan is incomplete: the time limit was reached before every cell was "
        "known");
  }
  if (!unseen.empty()) {
    warnings.push_back(
        fmt::format("{} hull cells are in no footprint of the flights", unseen.size()));
  }
  report["warnings"] = warnings;
  return report;
}

std::string preflight_markdown(const nlohmann::json& report) {
  std::string md = "# Pre-flight report\n\n## Sorties\n\n";
  md += "| UAV | sortie | launch site | waypoints | distance (m) | flight time (s) | files |\n";
  md += "|---|---|---|---|---|---|---|\n";
  for (const auto& s : report["sorties"]) {
    std::string files;
    for (const auto& [format, parts] : s["files"].items()) {
      files += fmt::format("{}{} {}", files.empty() ? "" : ", ", format, parts.get<int>());
    }
    md += fmt::format(
        "| {} | {} | {},{}{} | {} | {:.2f} | {:.1f} | {} |\n", s["uav"].get<int>(),
        s["sortie"].get<int>(), s["launch_site"][0].get<int>(), s["launch_site"][1].get<int>(),
        s["launch_site_given"].get<bool>() ? "" : " (below its start)", s["waypoints"].get<int>(),
        s["distance_m"].get<double>(), s["flight_time_s"].get<double>(), files);
  }
  const auto& c = report["cells"];
  md += fmt::format(
      "\n## Cells\n\n- hull cells: {}\n- unreachable (no allowed position sees them): {}\n"
      "- not detectable from z = 2: {}\n- in no footprint of the exported flights: {}\n",
      c["hull"].get<int>(), c["unreachable"].get<int>(), c["undetectable_from_z2"].get<int>(),
      c["unseen"].get<int>());
  const auto& sep = report["separation"];
  md += fmt::format("\n## Separation\n\n- planned with D = {}{}\n", sep["d"].get<int>(),
                    sep["d"].get<int>() == 0 ? " (none: UAVs may share a cell)" : " cells");
  if (!sep["min_cells"].is_null()) {
    md += fmt::format(
        "- smallest separation flown: {} cells ({:.2f} m), UAVs {} and {} at t = {} s\n",
        sep["min_cells"].get<int>(), sep["min_m"].get<double>(), sep["uavs"][0].get<int>(),
        sep["uavs"][1].get<int>(), sep["t_s"].get<double>());
  }
  md += fmt::format("- conflicts counted: {}\n", sep["conflicts"].get<long long>());
  md += "\n## Battery\n\nBattery margin: not computed (the mission has no endurance).\n";
  md += "\n## Warnings\n\n";
  if (report["warnings"].empty()) md += "None.\n";
  for (const auto& w : report["warnings"]) md += "- " + w.get<std::string>() + "\n";
  md += "\n![flights](preflight.svg)\n";
  return md;
}

std::string preflight_svg(const nlohmann::json& trace, const ExportPlan& plan,
                          const ExportSettings& settings) {
  constexpr int kPx = 4;  // pixels a cell; the grid's y grows upward on the picture
  const int w = plan.width * kPx, h = plan.height * kPx;
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} "
      "{}\">\n<rect width=\"{}\" height=\"{}\" fill=\"white\"/>\n",
      w, h, w, h, w, h);
  const auto cell = [&](int x, int y, const char* fill) {
    svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\"/>\n",
                       x * kPx, (plan.height - 1 - y) * kPx, kPx, kPx, fill);
  };
  for (int y = 0; y < plan.height; ++y) {
    for (int x = 0; x < plan.width; ++x) {
      if (plan.is_hull({x, y})) cell(x, y, "#dddddd");
    }
  }
  for (const auto& c : plan.no_fly) cell(c.x, c.y, "#ff4040");
  const auto report = preflight_report(trace, plan, {}, settings, std::nullopt);
  for (const auto& c : report["cells"]["unseen_cells"])
    cell(c[0].get<int>(), c[1].get<int>(), "black");
  const auto sorties = exported_sorties(plan, settings);
  for (const auto& s : sorties) {
    std::string points;
    for (const auto& wp : s.waypoints) {
      points += fmt::format("{},{} ", (wp.grid.cell.x + 0.5) * kPx,
                            (plan.height - 0.5 - wp.grid.cell.y) * kPx);
    }
    svg += fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1\"/>\n",
                       points, kColours[static_cast<std::size_t>(s.uav) % kColours.size()]);
    svg += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"none\" stroke=\"black\"/>\n",
                       (s.site.x + 0.5) * kPx, (plan.height - 0.5 - s.site.y) * kPx, 2 * kPx);
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace hullinspect::io
