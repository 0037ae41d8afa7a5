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
  auto sorties =
      plan_sorties(plan, settings.launch_sites, settings.flown_sorties, settings.launch_height_m);
  if (settings.simplify_m > 0) {
    for (auto& s : sorties) simplify_sortie(plan, s, settings.simplify_m);
  }
  return sorties;
}

double length(const ShipPose& a, const ShipPose& b) {
  return std::hypot(b.x - a.x, b.y - a.y, b.z - a.z);
}

struct Flight {
  double distance_m = 0;
  double time_s = 0;
};

// The climb from the sortie's home to the first of `waypoints`, every leg, the descent home; the
// time at the cruise speed plus every hold. Rounded as the report prints them.
Flight measure(const ExportPlan& plan, const Sortie& s,
               const std::vector<ExportWaypoint>& waypoints) {
  double distance = waypoints.empty() ? 0.0 : length(s.home, waypoints.front().pose);
  double holds = 0;
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    distance += length(waypoints[i - 1].pose, waypoints[i].pose);
    holds += hold_seconds(plan, waypoints[i], waypoints[i - 1]);
  }
  if (!waypoints.empty()) distance += length(waypoints.back().pose, s.home);
  return {std::round(distance * 100) / 100,
          std::round((distance / cruise_speed_mps(plan) + holds) * 10) / 10};
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
                                const std::optional<GeoReference>& geo,
                                const PreflightBattery& battery) {
  using nlohmann::json;
  const auto sorties = exported_sorties(plan, settings);
  json report;
  report["format"] = "hullinspect-preflight";
  report["version"] = 1;
  json rows = json::array();
  json warnings = json::array();
  struct Smallest {
    double margin;
    int uav;
    int sortie;
  };
  std::optional<Smallest> smallest;
  std::vector<std::vector<char>> seen(static_cast<std::size_t>(plan.height),
                                      std::vector<char>(static_cast<std::size_t>(plan.width), 0));
  for (const auto& s : sorties) {
    // The photos: the legs of the plan, not the flights to and from the launch site.
    mark_seen(plan,
              std::span<const ExportWaypoint>(s.waypoints)
                  .subspan(s.plan_begin(), s.plan_end() - s.plan_begin()),
              seen);
    json files = json::object();
    json file_names = json::object();  // the sortie's files of each format, in flight order
    for (const auto f : formats) {
      if (f == ExportFormat::kKml) continue;
      const int cap = settings.max_waypoints > 0 ? settings.max_waypoints : default_waypoint_cap(f);
      const auto split = split_sortie(s, cap);
      const auto parts = static_cast<int>(split.size());
      files[std::string(to_string(f))] = parts;
      json names = json::array();
      for (const auto& part : split) {
        for (auto& name : mission_file_names(f, part, settings)) names.push_back(std::move(name));
      }
      file_names[std::string(to_string(f))] = std::move(names);
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
                {"launch_site_given", s.given_site}};
    if (geo) {
      const auto h = geo->to_wgs84(s.home.x, s.home.y, s.home.z);
      row["home"] = {std::round(h.lat * 1e8) / 1e8, std::round(h.lon * 1e8) / 1e8};
    }
    const auto uav = static_cast<std::size_t>(s.uav);
    if (!battery.limited || uav >= battery.sorties.size() || battery.sorties[uav].empty()) {
      const auto flight = measure(plan, s, s.waypoints);
      row["waypoints"] = s.waypoints.size();
      row["distance_m"] = flight.distance_m;
      row["flight_time_s"] = flight.time_s;
      row["battery_margin_s"] = nullptr;  // unlimited flight: no battery to run out
      row["files"] = files;
      row["file_names"] = file_names;
      rows.push_back(row);
      continue;
    }
    const auto& planned = battery.sorties[uav];
    // The planned sorties this export sortie stands for: itself when the files were cut per
    // sortie, else every sortie of the UAV (its files then hold them as one flight).
    std::size_t first = 0;
    std::size_t count = planned.size();
    if (s.flown && static_cast<std::size_t>(s.number) <= planned.size()) {
      first = static_cast<std::size_t>(s.number) - 1;
      count = 1;
    } else if (planned.size() > 1) {
      warnings.push_back(fmt::format(
          "UAV {} flies {} sorties but its mission files hold them as one flight: land and swap "
          "the battery where the table's sorties end",
          s.uav, planned.size()));
    }
    for (std::size_t n = first; n < first + count; ++n) {
      const auto& p = planned[n];
      const double end_s = p.landing_s.value_or(battery.plan_end_s);
      // The sortie's waypoints: those the UAV's files reach between its take-off and landing
      // (all of a sortie's own files).
      std::vector<ExportWaypoint> flown;
      for (const auto& w : s.waypoints) {
        const double t = plan.seconds(w.grid.t);
        if (s.flown || (t >= p.takeoff_s && t <= end_s)) flown.push_back(w);
      }
      const double flight_s = end_s - p.takeoff_s;
      const double margin = battery.endurance_s - flight_s;
      json r = row;
      r["sortie"] = n + 1;
      r["launch_site_index"] = p.site;
      r["takeoff_s"] = p.takeoff_s;
      r["landing_s"] = p.landing_s ? json(*p.landing_s) : json(nullptr);
      r["waypoints"] = flown.size();
      r["distance_m"] = measure(plan, s, flown).distance_m;
      r["flight_time_s"] = flight_s;
      r["battery_margin_s"] = margin;
      r["files"] = files;
      r["file_names"] = file_names;
      if (!p.landing_s) {
        warnings.push_back(
            fmt::format("UAV {} sortie {}: still airborne when the plan ends", s.uav, n + 1));
      }
      if (margin < battery.reserve_s) {
        warnings.push_back(fmt::format(
            "UAV {} sortie {}: battery margin {:.1f} s is below the reserve of {:.1f} s", s.uav,
            n + 1, margin, battery.reserve_s));
      }
      if (!smallest || margin < smallest->margin) smallest = Smallest{margin, s.uav, int(n) + 1};
      rows.push_back(std::move(r));
    }
  }
  if (battery.limited) {
    report["battery"] = {{"limited", true},
                         {"endurance_s", battery.endurance_s},
                         {"reserve_s", battery.reserve_s},
                         {"min_margin_s", smallest ? json(smallest->margin) : json(nullptr)},
                         {"min_margin_uav", smallest ? json(smallest->uav) : json(nullptr)},
                         {"min_margin_sortie", smallest ? json(smallest->sortie) : json(nullptr)}};
  } else {
    report["battery"] = {{"limited", false},
                         {"note", "unlimited flight (no --endurance): no battery margin"}};
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
  // Heights the format means above mean sea level but which are ellipsoidal: no geoid model is
  // installed (docs/export.md "Altitudes: which frame each file is in").
  std::vector<std::string> sea_level;
  for (const auto f : formats) {
    if (f == ExportFormat::kQgc || f == ExportFormat::kWpl) sea_level.emplace_back(to_string(f));
  }
  if (!sea_level.empty() && !settings.geoid_height_m) {
    warnings.push_back(fmt::format(
        "{}: the planned home's altitude is its height above the WGS-84 ellipsoid, where the "
        "format means mean sea level (no geoid model); the waypoints are heights above home, "
        "which the vehicle takes at arming",
        fmt::join(sea_level, ", ")));
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
  md +=
      "| UAV | sortie | launch site | waypoints | distance (m) | flight time (s) | battery margin "
      "(s) | files |\n";
  md += "|---|---|---|---|---|---|---|---|\n";
  for (const auto& s : report["sorties"]) {
    std::vector<std::string> files;
    for (const auto& [format, names] : s["file_names"].items()) {
      for (const auto& name : names) files.push_back(name.get<std::string>());
    }
    md += fmt::format(
        "| {} | {} | {},{}{} | {} | {:.2f} | {:.1f} | {} | {} |\n", s["uav"].get<int>(),
        s["sortie"].get<int>(), s["launch_site"][0].get<int>(), s["launch_site"][1].get<int>(),
        s["launch_site_given"].get<bool>() ? "" : " (below its start)", s["waypoints"].get<int>(),
        s["distance_m"].get<double>(), s["flight_time_s"].get<double>(),
        s["battery_margin_s"].is_null()
            ? std::string("—")
            : fmt::format("{:.1f}", s["battery_margin_s"].get<double>()),
        files.empty() ? std::string("—") : fmt::format("{}", fmt::join(files, ", ")));
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
  const auto& battery = report["battery"];
  if (!battery["limited"].get<bool>()) {
    md += "\n## Battery\n\nBattery margin: none (unlimited flight: the plan has no --endurance).\n";
  } else {
    md += fmt::format(
        "\n## Battery\n\n- endurance {:.1f} s, reserve {:.1f} s\n- the margin of a sortie is the "
        "endurance less its flight time (take-off to landing)\n",
        battery["endurance_s"].get<double>(), battery["reserve_s"].get<double>());
    if (!battery["min_margin_s"].is_null()) {
      md += fmt::format("- smallest margin: {:.1f} s (UAV {} sortie {})\n",
                        battery["min_margin_s"].get<double>(), battery["min_margin_uav"].get<int>(),
                        battery["min_margin_sortie"].get<int>());
    }
  }
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
