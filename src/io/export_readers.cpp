#include "hullinspect/io/export_readers.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::io {

namespace {

constexpr int kNavWaypoint = 16;  // MAV_CMD_NAV_WAYPOINT

std::vector<std::string_view> split(std::string_view line, char sep) {
  std::vector<std::string_view> out;
  std::size_t at = 0;
  while (true) {
    const auto end = line.find(sep, at);
    out.push_back(
        line.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at));
    if (end == std::string_view::npos) return out;
    at = end + 1;
  }
}

double number(std::string_view s, const std::string& source, int line, std::string_view what) {
  double v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v)) {
    throw InputError(source, line, fmt::format("{}: '{}' is not a number", what, s));
  }
  return v;
}

// Lines without their '\n' (and a trailing '\r'); the last empty line after a final '\n' is
// dropped.
std::vector<std::string_view> lines(std::string_view text) {
  auto out = split(text, '\n');
  if (!out.empty() && out.back().empty()) out.pop_back();
  for (auto& l : out) {
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
  }
  return out;
}

}  // namespace

ReadPlan read_export_csv(std::string_view text, const std::string& source) {
  const auto rows = lines(text);
  if (rows.empty()) throw InputError(source, 1, "empty file (expected a header row)");
  const auto header = split(rows[0], ',');
  const std::vector<std::string_view> expected = {"index",      "t_s",     "x_m",   "y_m",
                                                  "z_m",        "yaw_deg", "plane", "action",
                                                  "duration_s", "cell_x",  "cell_y"};
  if (header.size() < expected.size() ||
      !std::equal(expected.begin(), expected.end(), header.begin())) {
    throw InputError(source, 1, "the header row is not the hullinspect waypoint csv header");
  }
  ReadPlan plan;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const int line = static_cast<int>(i) + 1;
    const auto f = split(rows[i], ',');
    if (f.size() != header.size()) {
      throw InputError(source, line,
                       fmt::format("expected {} fields, got {}", header.size(), f.size()));
    }
    ReadWaypoint w;
    w.t = number(f[1], source, line, "t_s");
    w.x = number(f[2], source, line, "x_m");
    w.y = number(f[3], source, line, "y_m");
    w.z = number(f[4], source, line, "z_m");
    w.yaw_deg = number(f[5], source, line, "yaw_deg");
    // Range-checked before the conversion, which is undefined for 1e56 (found by
    // fuzz_export_readers under UBSan).
    const double plane = number(f[6], source, line, "plane");
    if (!(plane >= -1e9 && plane <= 1e9)) {
      throw InputError(source, line, fmt::format("plane: '{}' is out of range", f[6]));
    }
    w.plane = static_cast<int>(plane);
    w.action = std::string(f[7]);
    plan.waypoints.push_back(w);
  }
  return plan;
}

ReadPlan read_qgc_plan(std::string_view text, const std::string& source) {
  using nlohmann::json;
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception&) {
    // Not only parse_error: a number too large for a double ("1e999") is out_of_range (406),
    // which escaped as an uncaught exception (found by fuzz_export_readers).
    throw InputError(source, 0, "not JSON");
  }
  auto need = [&](const json& j, const char* key, const std::string& where) -> const json& {
    if (!j.is_object() || !j.contains(key)) throw InputError(source, 0, where + key + ": missing");
    return j.at(key);
  };
  if (need(doc, "fileType", "") != "Plan")
    throw InputError(source, 0, "fileType: expected \"Plan\"");
  const auto& mission = need(doc, "mission", "");
  ReadPlan plan;
  const auto& home = need(mission, "plannedHomePosition", "mission.");
  if (!home.is_array() || home.size() != 3 || !home[0].is_number() || !home[1].is_number() ||
      !home[2].is_number()) {
    throw InputError(source, 0, "mission.plannedHomePosition: expected [lat, lon, alt]");
  }
  plan.home = {home[0].get<double>(), home[1].get<double>(), home[2].get<double>()};
  const auto& speed = need(mission, "cruiseSpeed", "mission.");
  if (!speed.is_number()) throw InputError(source, 0, "mission.cruiseSpeed: expected a number");
  plan.cruise_speed = speed.get<double>();
  const auto& items = need(mission, "items", "mission.");
  if (!items.is_array()) throw InputError(source, 0, "mission.items: expected an array");
  if (auto f = mission.find("firmwareType"); f != mission.end() && f->is_number_integer()) {
    plan.firmware = f->get<int>();
  }
  for (std::size_t i = 0; i < items.size(); ++i) {
    const auto where = fmt::format("mission.items[{}].", i);
    const auto& params = need(items[i], "params", where);
    const auto& command = need(items[i], "command", where);
    if (!command.is_number_integer()) {
      throw InputError(source, 0, where + "command: expected a MAVLink command number");
    }
    if (!params.is_array() || params.size() != 7) {
      throw InputError(source, 0, where + "params: expected 7 numbers");
    }
    ReadItem item;
    item.command = command.get<int>();
    if (auto f = items[i].find("frame"); f != items[i].end() && f->is_number_integer()) {
      item.frame = f->get<int>();
    }
    for (std::size_t j = 0; j < 7; ++j) {
      const auto& p = params[j];
      // QGroundControl writes an unset parameter (NaN) as null.
      if (p.is_null()) {
        item.params[j] = std::numeric_limits<double>::quiet_NaN();
      } else if (p.is_number()) {
        item.params[j] = p.get<double>();
      } else {
        throw InputError(source, 0, where + "params: expected 7 numbers");
      }
    }
    plan.items.push_back(item);
    if (item.command != kNavWaypoint) continue;
    ReadWaypoint w;
    w.hold_s = item.params[0];
    w.yaw_deg = item.params[3];
    w.geo = {item.params[4], item.params[5], item.params[6]};
    plan.waypoints.push_back(w);
  }
  return plan;
}

ReadPlan read_wpl(std::string_view text, const std::string& source) {
  const auto rows = lines(text);
  if (rows.empty() || rows[0] != "QGC WPL 110") {
    throw InputError(source, 1, "expected the header 'QGC WPL 110'");
  }
  ReadPlan plan;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const int line = static_cast<int>(i) + 1;
    const auto f = split(rows[i], '\t');
    if (f.size() != 12)
      throw InputError(source, line,
                       fmt::format("expected 12 tab-separated fields, got {}", f.size()));
    double v[12];
    for (std::size_t j = 0; j < 12; ++j) {
      // An unset parameter (P1–P4): hullinspect writes 0, QGroundControl nan.
      v[j] = j >= 4 && j < 8 && f[j] == "nan"
                 ? std::numeric_limits<double>::quiet_NaN()
                 : number(f[j], source, line, fmt::format("field {}", j + 1));
    }
    if (v[0] != static_cast<double>(i - 1)) {
      throw InputError(source, line,
                       fmt::format("index {} is out of sequence (expected {})", f[0], i - 1));
    }
    if (i == 1) {
      plan.home = {v[8], v[9], v[10]};
      continue;
    }
    ReadItem item;
    item.command = static_cast<int>(std::clamp(v[3], -1e9, 1e9));
    item.frame = static_cast<int>(std::clamp(v[2], -1e9, 1e9));
    std::copy(v + 4, v + 11, item.params.begin());
    plan.items.push_back(item);
    if (item.command != kNavWaypoint) continue;
    ReadWaypoint w;
    w.hold_s = v[4];
    w.yaw_deg = v[7];
    w.geo = {v[8], v[9], v[10]};
    plan.waypoints.push_back(w);
  }
  if (rows.size() < 2) throw InputError(source, 1, "no home line");
  return plan;
}

ReadPlan read_path_yaml(std::string_view text, const std::string& source) {
  YAML::Node doc;
  try {
    doc = YAML::Load(std::string(text));
  } catch (const YAML::Exception& e) {
    throw InputError(source, e.mark.line + 1, "not YAML");
  }
  ReadPlan plan;
  try {
    if (doc["header"]["frame_id"].as<std::string>() != "hull") {
      throw InputError(source, 0, "header.frame_id: expected hull");
    }
    for (const auto& p : doc["poses"]) {
      ReadWaypoint w;
      w.t = p["header"]["stamp"]["sec"].as<double>() +
            p["header"]["stamp"]["nanosec"].as<double>() * 1e-9;
      const auto pos = p["pose"]["position"];
      w.x = pos["x"].as<double>();
      w.y = pos["y"].as<double>();
      w.z = pos["z"].as<double>();
      const auto q = p["pose"]["orientation"];
      w.yaw_deg = 2 * std::atan2(q["z"].as<double>(), q["w"].as<double>()) * 180.0 / M_PI;
      plan.waypoints.push_back(w);
    }
  } catch (const YAML::Exception& e) {
    throw InputError(
        source, e.mark.line + 1,
        "not a nav_msgs/Path (header, poses[].header.stamp, pose.position, pose.orientation)");
  }
  return plan;
}

}  // namespace hullinspect::io
