#include "hullinspect/world/hull_geometry.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/files/json_document.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/ship_frame_bounds.hpp"

namespace hullinspect::world {

namespace {

constexpr std::string_view kFormat = "hullinspect-hull";
constexpr int kVersion = 1;
constexpr std::string_view kAxisNames = "xyz";

[[noreturn]] void fail(const std::string& source, const std::string& field,
                       const std::string& problem) {
  throw InputError(source, 0, fmt::format("{}: {}", field, problem));
}

}  // namespace

std::string_view to_string(HullSide side) {
  switch (side) {
    case HullSide::port:
      return "port";
    case HullSide::both:
      return "both";
    case HullSide::starboard:
      break;
  }
  return "starboard";
}

HullSide parse_hull_side(std::string_view text) {
  if (text == "starboard") return HullSide::starboard;
  if (text == "port") return HullSide::port;
  if (text == "both") return HullSide::both;
  throw ParameterError("side", fmt::format("expected port, starboard or both, got '{}'", text));
}

AxisMap AxisMap::parse(std::string_view text) {
  const auto bad = [&] {
    return ParameterError(
        "axes", fmt::format("expected a signed permutation of x,y,z like x,-z,y, got '{}'", text));
  };
  AxisMap m;
  std::array<bool, 3> used{false, false, false};
  std::size_t pos = 0;
  for (int i = 0; i < 3; ++i) {
    const std::size_t end = text.find(',', pos);
    if ((i < 2) != (end != std::string_view::npos)) throw bad();
    std::string_view part = text.substr(pos, end == std::string_view::npos ? text.npos : end - pos);
    pos = end + 1;
    int sign = 1;
    if (!part.empty() && (part[0] == '-' || part[0] == '+')) {
      sign = part[0] == '-' ? -1 : 1;
      part.remove_prefix(1);
    }
    if (part.size() != 1) throw bad();
    const std::size_t axis = kAxisNames.find(part[0]);
    if (axis == std::string_view::npos || used[axis]) throw bad();
    used[axis] = true;
    m.axis[static_cast<std::size_t>(i)] = static_cast<int>(axis);
    m.sign[static_cast<std::size_t>(i)] = sign;
  }
  return m;
}

std::string AxisMap::to_string() const {
  std::string out;
  for (std::size_t i = 0; i < 3; ++i) {
    if (i) out += ',';
    if (sign[i] < 0) out += '-';
    out += kAxisNames[static_cast<std::size_t>(axis[i])];
  }
  return out;
}

int AxisMap::determinant() const {
  // Parity of the permutation times the product of the signs.
  int inversions = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = i + 1; j < 3; ++j) inversions += axis[i] > axis[j] ? 1 : 0;
  }
  return (inversions % 2 ? -1 : 1) * sign[0] * sign[1] * sign[2];
}

void validate(const HullGeometry& g, const HullMask& mask, const std::string& source) {
  if (!(g.cell_size >= kMinCellSizeM && g.cell_size <= kMaxCellSizeM)) {
    fail(source, "cell_size",
         fmt::format("must be metres in [{}, {}] (got {})", kMinCellSizeM, kMaxCellSizeM,
                     g.cell_size));
  }
  const auto within_frame = [](double v) { return std::abs(v) <= kMaxShipFrameM; };
  if (!within_frame(g.x0) || !within_frame(g.z0)) {
    fail(source, "origin",
         fmt::format("must be metres in [{}, {}] (got [{}, {}])", -kMaxShipFrameM, kMaxShipFrameM,
                     g.x0, g.z0));
  }
  if (!within_frame(g.side_plane_y)) {
    fail(source, "side_plane_y",
         fmt::format("must be metres in [{}, {}] (got {})", -kMaxShipFrameM, kMaxShipFrameM,
                     g.side_plane_y));
  }
  if (!(g.scale > 0) || !std::isfinite(g.scale)) fail(source, "scale", "must be positive");
  if (!(g.min_coverage > 0 && g.min_coverage <= 1)) {
    fail(source, "min_coverage", "must be in (0, 1]");
  }
  if (g.waterline && !std::isfinite(*g.waterline)) fail(source, "waterline", "must be finite");
  const auto check_size = [&](const char* field, int w, int h) {
    if (w != mask.width() || h != mask.height()) {
      fail(source, field,
           fmt::format("is {} × {} but the mask is {} × {}", w, h, mask.width(), mask.height()));
    }
  };
  check_size("depth", g.depth.width(), g.depth.height());
  check_size("normal", g.normal.width(), g.normal.height());
  check_size("coverage", g.coverage.width(), g.coverage.height());
  if (g.unrolled()) {
    check_size("surface", g.surface.width(), g.surface.height());
  } else if (g.surface.size() != 0) {
    fail(source, "surface", "is only for an unrolled hull (side both)");
  }
  if (g.seam && !g.unrolled()) fail(source, "seam", "is only for an unrolled hull (side both)");
  if (g.seam && mask.width() < 3) {
    fail(source, "seam",
         fmt::format("needs a grid at least 3 columns wide (got {})", mask.width()));
  }
  for (int y = 0; y < mask.height(); ++y) {
    for (int x = 0; x < mask.width(); ++x) {
      const float d = g.depth(x, y);
      if (!(d >= 0 && d <= kMaxShipFrameM)) {
        fail(source, "depth", fmt::format("cell ({}, {}) is {}; expected metres >= 0", x, y, d));
      }
      const float c = g.coverage(x, y);
      if (!(c >= 0 && c <= 1)) {
        fail(source, "coverage", fmt::format("cell ({}, {}) is {}; expected 0..1", x, y, c));
      }
      if (g.unrolled()) {
        const Point3 p = g.surface(x, y);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
          fail(source, "surface", fmt::format("cell ({}, {}) is not a finite point", x, y));
        }
      }
      const Normal n = g.normal(x, y);
      const double len = std::sqrt(double(n.x) * n.x + double(n.y) * n.y + double(n.z) * n.z);
      if (!(std::abs(len - 1.0) < 1e-3)) {
        fail(source, "normal",
             fmt::format("cell ({}, {}) has length {:.4f}; expected a unit vector", x, y, len));
      }
    }
  }
}

void HullMask::attach_geometry(HullGeometry geometry) {
  validate(geometry, *this, source_);
  geometry_ = std::make_shared<const HullGeometry>(std::move(geometry));
}

namespace {

using nlohmann::json;

const json& field(const json& doc, const char* name, const std::string& source) {
  const auto it = doc.find(name);
  if (it == doc.end()) fail(source, name, "missing");
  return *it;
}

double number(const json& doc, const char* name, const std::string& source) {
  const json& v = field(doc, name, source);
  if (!v.is_number()) fail(source, name, "expected a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) fail(source, name, "expected a finite number");
  return d;
}

std::string text(const json& doc, const char* name, const std::string& source) {
  const json& v = field(doc, name, source);
  if (!v.is_string()) fail(source, name, "expected a string");
  return v.get<std::string>();
}

int side_length(const json& doc, const char* name, const std::string& source) {
  const json& v = field(doc, name, source);
  if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > kMaxGridSide) {
    fail(source, name, fmt::format("expected an integer in 1..{}", kMaxGridSide));
  }
  return v.get<int>();
}

/// Reads field[y][x] (rows bottom first) as `height` rows of `width` items, each read by `item`.
template <class T, class Item>
grid::Grid<T> rows(const json& doc, const char* name, int width, int height,
                   const std::string& source, Item item) {
  const json& v = field(doc, name, source);
  if (!v.is_array() || v.size() != static_cast<std::size_t>(height)) {
    fail(source, name, fmt::format("expected {} rows", height));
  }
  grid::Grid<T> g(width, height);
  for (int y = 0; y < height; ++y) {
    const json& row = v[static_cast<std::size_t>(y)];
    if (!row.is_array() || row.size() != static_cast<std::size_t>(width)) {
      fail(source, name, fmt::format("row {} must have {} values", y, width));
    }
    for (int x = 0; x < width; ++x) {
      g(x, y) = item(row[static_cast<std::size_t>(x)], x, y);
    }
  }
  return g;
}

float cell_number(const json& v, const char* name, int x, int y, const std::string& source) {
  if (!v.is_number()) fail(source, name, fmt::format("cell ({}, {}) is not a number", x, y));
  return v.get<float>();
}

double rounded(double v, double unit) {
  return std::round(v / unit) * unit;
}

}  // namespace

HullMask parse_hull_json(std::string_view bytes, const std::string& source) {
  // The shared reader: a number no double holds (0.1e4000, found by the CLI mutation test) is an
  // InputError naming the line and field, not nlohmann's out_of_range (exit 1).
  const json doc = io::parse_json_document(bytes, source, "valid JSON");
  if (!doc.is_object()) fail(source, "format", "expected a JSON object");
  if (text(doc, "format", source) != kFormat) {
    fail(source, "format", fmt::format("expected \"{}\"", kFormat));
  }
  const json& version = field(doc, "version", source);
  if (version != kVersion) fail(source, "version", fmt::format("expected {}", kVersion));
  const int width = side_length(doc, "width", source);
  const int height = side_length(doc, "height", source);
  grid::Grid<std::uint8_t> is_hull =
      rows<std::uint8_t>(doc, "mask", width, height, source, [&](const json& v, int x, int y) {
        if (v != 0 && v != 1)
          fail(source, "mask", fmt::format("cell ({}, {}) is not 0 or 1", x, y));
        return static_cast<std::uint8_t>(v.get<int>());
      });
  HullMask mask(std::move(is_hull), source);

  HullGeometry g;
  g.cell_size = number(doc, "cell_size", source);
  const json& origin = field(doc, "origin", source);
  if (!origin.is_array() || origin.size() != 2 || !origin[0].is_number() ||
      !origin[1].is_number()) {
    fail(source, "origin", "expected [X0, Z0] in metres");
  }
  g.x0 = origin[0].get<double>();
  g.z0 = origin[1].get<double>();
  g.side_plane_y = number(doc, "side_plane_y", source);
  try {
    g.side = parse_hull_side(text(doc, "side", source));
    g.axes = AxisMap::parse(text(doc, "axes", source));
  } catch (const ParameterError& e) {
    fail(source, e.name(), e.problem());
  }
  g.scale = number(doc, "scale", source);
  g.min_coverage = number(doc, "min_coverage", source);
  const json& waterline = field(doc, "waterline", source);
  if (!waterline.is_null()) g.waterline = number(doc, "waterline", source);
  if (const auto it = doc.find("mesh"); it != doc.end()) {
    if (!it->is_string()) fail(source, "mesh", "expected a string");
    g.mesh = it->get<std::string>();
  }
  if (const auto it = doc.find("seam"); it != doc.end()) {
    if (!it->is_boolean()) fail(source, "seam", "expected true or false");
    g.seam = it->get<bool>();
  }
  g.depth = rows<float>(doc, "depth", width, height, source, [&](const json& v, int x, int y) {
    return cell_number(v, "depth", x, y, source);
  });
  g.coverage = rows<float>(
      doc, "coverage", width, height, source,
      [&](const json& v, int x, int y) { return cell_number(v, "coverage", x, y, source); });
  g.normal = rows<Normal>(doc, "normal", width, height, source, [&](const json& v, int x, int y) {
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() ||
        !v[2].is_number()) {
      fail(source, "normal", fmt::format("cell ({}, {}) is not [nx, ny, nz]", x, y));
    }
    return Normal{v[0].get<float>(), v[1].get<float>(), v[2].get<float>()};
  });
  if (g.unrolled()) {
    g.surface =
        rows<Point3>(doc, "surface", width, height, source, [&](const json& v, int x, int y) {
          if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() ||
              !v[2].is_number()) {
            fail(source, "surface", fmt::format("cell ({}, {}) is not [X, Y, Z]", x, y));
          }
          return Point3{v[0].get<float>(), v[1].get<float>(), v[2].get<float>()};
        });
  }
  mask.attach_geometry(std::move(g));
  return mask;
}

std::string to_hull_json(const HullMask& hull) {
  const HullGeometry* g = hull.geometry();
  if (g == nullptr) throw LogicError("to_hull_json: the hull has no geometry");
  json doc = json::object();
  doc["format"] = kFormat;
  doc["version"] = kVersion;
  doc["mesh"] = g->mesh;
  doc["side"] = to_string(g->side);
  doc["axes"] = g->axes.to_string();
  doc["scale"] = g->scale;
  doc["cell_size"] = g->cell_size;
  doc["min_coverage"] = g->min_coverage;
  doc["waterline"] = g->waterline ? json(*g->waterline) : json(nullptr);
  doc["origin"] = {g->x0, g->z0};
  doc["side_plane_y"] = g->side_plane_y;
  doc["width"] = hull.width();
  doc["height"] = hull.height();
  json mask = json::array(), depth = json::array(), normal = json::array(),
       coverage = json::array();
  for (int y = 0; y < hull.height(); ++y) {
    json m = json::array(), d = json::array(), n = json::array(), c = json::array();
    for (int x = 0; x < hull.width(); ++x) {
      m.push_back(hull.is_hull(x, y) ? 1 : 0);
      d.push_back(rounded(g->depth(x, y), 1e-4));
      c.push_back(rounded(g->coverage(x, y), 1e-4));
      const Normal v = g->normal(x, y);
      n.push_back({rounded(v.x, 1e-6), rounded(v.y, 1e-6), rounded(v.z, 1e-6)});
    }
    mask.push_back(std::move(m));
    depth.push_back(std::move(d));
    normal.push_back(std::move(n));
    coverage.push_back(std::move(c));
  }
  doc["mask"] = std::move(mask);
  doc["depth"] = std::move(depth);
  doc["normal"] = std::move(normal);
  doc["coverage"] = std::move(coverage);
  if (g->unrolled()) {
    json surface = json::array();
    for (int y = 0; y < hull.height(); ++y) {
      json row = json::array();
      for (int x = 0; x < hull.width(); ++x) {
        const Point3 p = g->surface(x, y);
        row.push_back({rounded(p.x, 1e-4), rounded(p.y, 1e-4), rounded(p.z, 1e-4)});
      }
      surface.push_back(std::move(row));
    }
    doc["surface"] = std::move(surface);
    doc["seam"] = g->seam;
  }
  return doc.dump() + "\n";
}

}  // namespace hullinspect::world
