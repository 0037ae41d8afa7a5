// dji-kmz: a DJI WPML wayline (KMZ = zip of wpmz/template.kml and wpmz/waylines.wpml, namespace
// http://www.dji.com/wpmz/1.0.2), as DJI Pilot 2 and FlightHub 2 load them. Heights are above
// the take-off point (relativeToStartPoint); each placemark has the heading that faces the hull,
// the gimbal pitch where it changes, a hover where the plan holds, and one distance-triggered
// photo group covers the plan's legs.

#include <fmt/format.h>
#include <zip.h>

#include <pugixml.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "export_writers.hpp"
#include "hullinspect/core/errors.hpp"

namespace hullinspect::io::detail {

namespace {

constexpr const char* kWpmlNamespace = "http://www.dji.com/wpmz/1.0.2";

struct DroneEnum {
  int drone, drone_sub, payload;
};

// DJI's enumeration values (Cloud API, WPML common elements): aircraft and its standard camera.
DroneEnum drone_enum(DjiDrone d) {
  switch (d) {
    case DjiDrone::kM350:
      return {89, 0, 42};  // H20
    case DjiDrone::kM300:
      return {60, 0, 42};  // H20
    case DjiDrone::kM30:
      return {67, 0, 52};
    case DjiDrone::kM30T:
      return {67, 1, 53};
    case DjiDrone::kM3E:
      return {77, 0, 66};
  }
  return {89, 0, 42};
}

void add(pugi::xml_node parent, const char* name, const std::string& text) {
  parent.append_child(name).text().set(text.c_str());
}

std::string num(double v) {
  return fmt::format("{:.4f}", v);
}

// [-180, 180]: WPML's heading angle.
double signed_heading(double compass) {
  return compass > 180 ? compass - 360 : compass;
}

void mission_config(pugi::xml_node document, const MissionPart& part, const GeoReference& geo,
                    const ExportSettings& settings, double speed, double first_height,
                    bool with_ref_point) {
  auto c = document.append_child("wpml:missionConfig");
  add(c, "wpml:flyToWaylineMode", "safely");
  add(c, "wpml:finishAction",
      !part.lands()                           ? "noAction"
      : settings.finish == FinishAction::kRtl ? "goHome"
                                              : "autoLand");
  add(c, "wpml:exitOnRCLost", "executeLostAction");
  add(c, "wpml:executeRCLostAction", "goBack");
  add(c, "wpml:takeOffSecurityHeight", num(std::clamp(first_height, 1.2, 1500.0)));
  if (with_ref_point) {
    const GeoPoint home = home_point(part, geo);
    add(c, "wpml:takeOffRefPoint",
        fmt::format("{:.10f},{:.10f},{:.4f}", home.lat, home.lon, home.alt));
  }
  add(c, "wpml:globalTransitionalSpeed", num(speed));
  const auto e = drone_enum(settings.drone);
  auto drone = c.append_child("wpml:droneInfo");
  add(drone, "wpml:droneEnumValue", std::to_string(e.drone));
  add(drone, "wpml:droneSubEnumValue", std::to_string(e.drone_sub));
  auto payload = c.append_child("wpml:payloadInfo");
  add(payload, "wpml:payloadEnumValue", std::to_string(e.payload));
  add(payload, "wpml:payloadPositionIndex", "0");
}

pugi::xml_node kml_document(pugi::xml_document& doc) {
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  auto kml = doc.append_child("kml");
  kml.append_attribute("xmlns") = "http://www.opengis.net/kml/2.2";
  kml.append_attribute("xmlns:wpml") = kWpmlNamespace;
  return kml.append_child("Document");
}

void action(pugi::xml_node group, int id, const char* func,
            const std::vector<std::pair<const char*, std::string>>& params) {
  auto a = group.append_child("wpml:action");
  add(a, "wpml:actionId", std::to_string(id));
  add(a, "wpml:actionActuatorFunc", func);
  auto p = a.append_child("wpml:actionActuatorFuncParam");
  for (const auto& [name, value] : params) add(p, name, value);
}

pugi::xml_node action_group(pugi::xml_node placemark, int id, std::size_t begin, std::size_t end,
                            const char* trigger, const std::string& trigger_param = {}) {
  auto g = placemark.append_child("wpml:actionGroup");
  add(g, "wpml:actionGroupId", std::to_string(id));
  add(g, "wpml:actionGroupStartIndex", std::to_string(begin));
  add(g, "wpml:actionGroupEndIndex", std::to_string(end));
  add(g, "wpml:actionGroupMode", "sequence");
  auto t = g.append_child("wpml:actionTrigger");
  add(t, "wpml:actionTriggerType", trigger);
  if (!trigger_param.empty()) add(t, "wpml:actionTriggerParam", trigger_param);
  return g;
}

// The placemarks of one file: `execute` = waylines.wpml (executeHeight) or template.kml (height).
void placemarks(pugi::xml_node folder, const ExportPlan& plan, const MissionPart& part,
                const std::vector<GeoWaypoint>& points, bool execute) {
  // The part's waypoints that lie on the plan: photos every cell along their legs.
  std::size_t photo_begin = points.size(), photo_end = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t s = part.offset() + i;
    if (s >= part.sortie->plan_begin() && s < part.sortie->plan_end()) {
      photo_begin = std::min(photo_begin, i);
      photo_end = i;
    }
  }
  int group_id = 0;
  int action_id = 0;
  double pitch = NAN;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    auto pm = folder.append_child("Placemark");
    add(pm.append_child("Point"), "coordinates", fmt::format("{:.10f},{:.10f}", p.lon, p.lat));
    add(pm, "wpml:index", std::to_string(i));
    add(pm, execute ? "wpml:executeHeight" : "wpml:height", num(p.rel_alt));
    add(pm, "wpml:waypointSpeed", num(cruise_speed_mps(plan)));
    auto heading = pm.append_child("wpml:waypointHeadingParam");
    add(heading, "wpml:waypointHeadingMode", "smoothTransition");
    add(heading, "wpml:waypointHeadingAngle", fmt::format("{:.3f}", signed_heading(p.yaw_deg)));
    add(heading, "wpml:waypointHeadingPathMode", "followBadArc");
    auto turn = pm.append_child("wpml:waypointTurnParam");
    add(turn, "wpml:waypointTurnMode", "toPointAndStopWithDiscontinuityCurvature");
    add(turn, "wpml:waypointTurnDampingDist", "0");
    add(pm, "wpml:useStraightLine", "1");
    const bool new_pitch = !(std::abs(p.gimbal_pitch_deg - pitch) < 0.5);
    if (new_pitch || p.hold_s > 0) {
      auto g = action_group(pm, group_id++, i, i, "reachPoint");
      if (new_pitch) {
        action(g, action_id++, "gimbalRotate",
               {{"wpml:gimbalRotateMode", "absoluteAngle"},
                {"wpml:gimbalPitchRotateEnable", "1"},
                {"wpml:gimbalPitchRotateAngle", fmt::format("{:.3f}", p.gimbal_pitch_deg)},
                {"wpml:gimbalRollRotateEnable", "0"},
                {"wpml:gimbalRollRotateAngle", "0"},
                {"wpml:gimbalYawRotateEnable", "0"},
                {"wpml:gimbalYawRotateAngle", "0"},
                {"wpml:gimbalRotateTimeEnable", "0"},
                {"wpml:gimbalRotateTime", "0"},
                {"wpml:payloadPositionIndex", "0"}});
        pitch = p.gimbal_pitch_deg;
      }
      if (p.hold_s > 0) action(g, action_id++, "hover", {{"wpml:hoverTime", num(p.hold_s)}});
    }
    if (i == photo_begin && photo_end > photo_begin) {
      auto g = action_group(pm, group_id++, photo_begin, photo_end, "multipleDistance",
                            num(photo_distance_m(plan)));
      action(g, action_id++, "takePhoto", {{"wpml:payloadPositionIndex", "0"}});
    }
  }
}

std::string xml_text(const pugi::xml_document& doc) {
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

// A zip archive of the named entries, built in memory with fixed timestamps (same input, same
// bytes).
std::string zip_archive(const std::vector<std::pair<std::string, std::string>>& entries) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* buffer = zip_source_buffer_create(nullptr, 0, 0, &error);
  if (!buffer) throw std::runtime_error("zip: cannot create a buffer");
  zip_source_keep(buffer);
  zip_t* archive = zip_open_from_source(buffer, ZIP_TRUNCATE, &error);
  if (!archive) {
    zip_source_free(buffer);
    throw std::runtime_error("zip: cannot open an archive");
  }
  constexpr time_t kFixedTime = 315532800;  // 1980-01-01, zip's earliest
  for (const auto& [name, content] : entries) {
    zip_source_t* s = zip_source_buffer(archive, content.data(), content.size(), 0);
    const zip_int64_t index = s ? zip_file_add(archive, name.c_str(), s, ZIP_FL_ENC_UTF_8) : -1;
    if (index < 0) {
      if (s) zip_source_free(s);
      zip_discard(archive);
      zip_source_free(buffer);
      throw std::runtime_error("zip: cannot add " + name);
    }
    zip_file_set_mtime(archive, static_cast<zip_uint64_t>(index), kFixedTime, 0);
  }
  if (zip_close(archive) != 0) {
    zip_discard(archive);
    zip_source_free(buffer);
    throw std::runtime_error("zip: cannot write the archive");
  }
  std::string bytes;
  if (zip_source_open(buffer) == 0) {
    zip_source_seek(buffer, 0, SEEK_END);
    bytes.resize(static_cast<std::size_t>(zip_source_tell(buffer)));
    zip_source_seek(buffer, 0, SEEK_SET);
    zip_source_read(buffer, bytes.data(), bytes.size());
    zip_source_close(buffer);
  }
  zip_source_free(buffer);
  return bytes;
}

}  // namespace

std::string write_dji_kmz(const ExportPlan& plan, const MissionPart& part, const GeoReference& geo,
                          const ExportSettings& settings) {
  const auto points = geo_waypoints(plan, part, geo);
  const double speed = cruise_speed_mps(plan);
  const double first_height = points.empty() ? 1.2 : points.front().rel_alt;

  pugi::xml_document templ;
  auto tdoc = kml_document(templ);
  mission_config(tdoc, part, geo, settings, speed, first_height, true);
  auto tfolder = tdoc.append_child("Folder");
  add(tfolder, "wpml:templateType", "waypoint");
  add(tfolder, "wpml:templateId", "0");
  auto sys = tfolder.append_child("wpml:waylineCoordinateSysParam");
  add(sys, "wpml:coordinateMode", "WGS84");
  add(sys, "wpml:heightMode", "relativeToStartPoint");
  add(tfolder, "wpml:autoFlightSpeed", num(speed));
  add(tfolder, "wpml:gimbalPitchMode", "usePointSetting");
  add(tfolder, "wpml:globalUseStraightLine", "1");
  placemarks(tfolder, plan, part, points, false);

  pugi::xml_document waylines;
  auto wdoc = kml_document(waylines);
  mission_config(wdoc, part, geo, settings, speed, first_height, false);
  auto wfolder = wdoc.append_child("Folder");
  add(wfolder, "wpml:templateId", "0");
  add(wfolder, "wpml:executeHeightMode", "relativeToStartPoint");
  add(wfolder, "wpml:waylineId", "0");
  add(wfolder, "wpml:autoFlightSpeed", num(speed));
  placemarks(wfolder, plan, part, points, true);

  return zip_archive(
      {{"wpmz/template.kml", xml_text(templ)}, {"wpmz/waylines.wpml", xml_text(waylines)}});
}

}  // namespace hullinspect::io::detail
