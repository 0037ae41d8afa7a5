// kml: a Google Earth preview of the whole fleet in one file: a coloured line per UAV and sortie,
// the launch sites as points, the no-fly positions as 3D boxes (runs of no-fly cells along a row,
// from the plane-1 to the plane-2 stand-off). Heights are above the grid's bottom edge
// (altitudeMode relativeToGround): a preview, not a flight file.

#include <fmt/format.h>

#include <pugixml.hpp>

#include <array>
#include <set>
#include <sstream>

#include "export_writers.hpp"

namespace hullinspect::io::detail {

namespace {

// KML colours are aabbggrr; one per UAV, cycling.
constexpr std::array<const char*, 8> kColours = {"ff0000ff", "ffff0000", "ff00aa00", "ff00ffff",
                                                 "ffff00ff", "ffffff00", "ff0080ff", "ff808080"};

// A ship-frame point as "lon,lat,height" with height above the grid's bottom edge.
std::string coordinate(const ExportPlan& plan, const GeoReference& geo, double x, double y,
                       double z) {
  const GeoPoint p = geo.to_wgs84(x, y, z);
  const GeoPoint base = geo.to_wgs84(x, y, plan.frame.spec().z0);
  return fmt::format("{:.10f},{:.10f},{:.4f}", p.lon, p.lat, p.alt - base.alt);
}

void add_text(pugi::xml_node parent, const char* name, const std::string& text) {
  parent.append_child(name).text().set(text.c_str());
}

void add_no_fly_boxes(pugi::xml_node folder, const ExportPlan& plan, const GeoReference& geo) {
  const std::set<grid::Cell> cells(plan.no_fly.begin(), plan.no_fly.end());
  const double half = plan.frame.spec().cell_m / 2;
  for (auto it = cells.begin(); it != cells.end();) {
    // A run of no-fly cells along one row becomes one box.
    const grid::Cell first = *it;
    grid::Cell last = first;
    // (On an unrolled hull each cell is a box of its own: a row curves around the ship.)
    while (++it != cells.end() && !plan.frame.unrolled() && it->y == last.y &&
           it->x == last.x + 1) {
      last = *it;
    }
    const auto a1 = plan.frame.pose(first, 1), a2 = plan.frame.pose(first, 2);
    const auto b1 = plan.frame.pose(last, 1), b2 = plan.frame.pose(last, 2);
    const double x0 = a1.x - half, x1 = b1.x + half;
    const double y0 = std::min({a1.y, a2.y, b1.y, b2.y}) - half;
    const double y1 = std::max({a1.y, a2.y, b1.y, b2.y}) + half;
    const double z0 = a1.z - half, z1 = a1.z + half;
    auto placemark = folder.append_child("Placemark");
    add_text(placemark, "name",
             fmt::format("no-fly {},{}–{},{}", first.x, first.y, last.x, last.y));
    add_text(placemark, "styleUrl", "#no-fly");
    auto multi = placemark.append_child("MultiGeometry");
    const std::array<std::array<double, 3>, 8> v = {{{x0, y0, z0},
                                                     {x1, y0, z0},
                                                     {x1, y1, z0},
                                                     {x0, y1, z0},
                                                     {x0, y0, z1},
                                                     {x1, y0, z1},
                                                     {x1, y1, z1},
                                                     {x0, y1, z1}}};
    const std::array<std::array<int, 4>, 6> faces = {
        {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
    for (const auto& f : faces) {
      auto polygon = multi.append_child("Polygon");
      add_text(polygon, "altitudeMode", "relativeToGround");
      std::string ring;
      for (int k : {f[0], f[1], f[2], f[3], f[0]}) {
        const auto& p = v[static_cast<std::size_t>(k)];
        ring += coordinate(plan, geo, p[0], p[1], p[2]) + " ";
      }
      ring.pop_back();
      add_text(polygon.append_child("outerBoundaryIs").append_child("LinearRing"), "coordinates",
               ring);
    }
  }
}

}  // namespace

std::string write_kml(const ExportPlan& plan, const std::vector<Sortie>& sorties,
                      const GeoReference& geo) {
  pugi::xml_document doc;
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  auto kml = doc.append_child("kml");
  kml.append_attribute("xmlns") = "http://www.opengis.net/kml/2.2";
  auto document = kml.append_child("Document");
  add_text(document, "name", "hullinspect mission");
  add_text(document, "description",
           "Flight lines per UAV and sortie, launch sites and no-fly zones; heights above the "
           "hull grid's bottom edge.");
  for (std::size_t c = 0; c < kColours.size(); ++c) {
    auto style = document.append_child("Style");
    style.append_attribute("id") = fmt::format("uav{}", c).c_str();
    auto line = style.append_child("LineStyle");
    add_text(line, "color", kColours[c]);
    add_text(line, "width", "2");
  }
  auto no_fly_style = document.append_child("Style");
  no_fly_style.append_attribute("id") = "no-fly";
  add_text(no_fly_style.append_child("PolyStyle"), "color", "800000ff");

  auto flights = document.append_child("Folder");
  add_text(flights, "name", "Flights");
  for (const auto& s : sorties) {
    auto placemark = flights.append_child("Placemark");
    add_text(placemark, "name", fmt::format("UAV {} sortie {}", s.uav, s.number));
    add_text(placemark, "styleUrl",
             fmt::format("#uav{}", static_cast<std::size_t>(s.uav) % kColours.size()));
    auto line = placemark.append_child("LineString");
    add_text(line, "altitudeMode", "relativeToGround");
    std::string coordinates = coordinate(plan, geo, s.home.x, s.home.y, s.home.z);
    for (const auto& w : s.waypoints) {
      coordinates += " " + coordinate(plan, geo, w.pose.x, w.pose.y, w.pose.z);
    }
    coordinates += " " + coordinate(plan, geo, s.home.x, s.home.y, s.home.z);
    add_text(line, "coordinates", coordinates);
  }
  auto sites = document.append_child("Folder");
  add_text(sites, "name", "Launch sites");
  std::set<grid::Cell> seen;
  for (const auto& s : sorties) {
    if (!seen.insert(s.site).second) continue;
    auto placemark = sites.append_child("Placemark");
    add_text(placemark, "name", fmt::format("launch site {},{}", s.site.x, s.site.y));
    add_text(placemark.append_child("Point"), "coordinates",
             coordinate(plan, geo, s.home.x, s.home.y, s.home.z));
  }
  auto zones = document.append_child("Folder");
  add_text(zones, "name", "No-fly zones");
  add_no_fly_boxes(zones, plan, geo);
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

}  // namespace hullinspect::io::detail
