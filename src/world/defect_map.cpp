#include "hullinspect/world/defect_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"
#include "hullinspect/files/bounded_read.hpp"
#include "hullinspect/files/json_document.hpp"

namespace hullinspect::world {

namespace {

// A survey list is small; anything near this is not one.
constexpr std::size_t kMaxDefectFileBytes = std::size_t{16} << 20;

// The largest defect or offset accepted, in metres: far beyond any ship.
constexpr double kMaxMetres = 1e5;

// Where a mask without a mesh sits in the ship frame (docs/export.md, "Frames").
constexpr double kMaskCellSize = 0.5;

double metres(std::string_view text, const std::string& field, double min) {
  try {
    return parse_real(text, min, kMaxMetres);
  } catch (const NumberError& e) {
    throw NumberError(fmt::format("{}: {}", field, e.what()));
  }
}

HullSide side_of(std::string_view text) {
  if (text == "starboard") return HullSide::starboard;
  if (text == "port") return HullSide::port;
  throw NumberError(
      fmt::format("side: must be port or starboard (got '{}')", escape_for_message(text)));
}

// The text fields of one defect (CSV cells or JSON values as text) to a Defect.
Defect defect_from(const std::map<std::string, std::string>& fields, const FrameSpacing& frames,
                   int line, std::string where) {
  Defect d;
  d.line = line;
  d.where = std::move(where);
  if (const auto x = fields.find("x_m"); x != fields.end()) {
    d.x_m = metres(x->second, "x_m", -kMaxMetres);
  } else {
    const double frame = metres(fields.at("frame"), "frame", -kMaxMetres);
    if (!frames.frame_spacing_m) {
      throw NumberError("frame: a frame number needs the frame spacing (--frame-spacing)");
    }
    d.x_m = frames.frame_zero_m + frame * *frames.frame_spacing_m;
  }
  d.z_m = metres(fields.at("z_m"), "z_m", -kMaxMetres);
  d.side = side_of(fields.at("side"));
  d.w_m = metres(fields.at("w_m"), "w_m", 0);
  d.h_m = metres(fields.at("h_m"), "h_m", 0);
  if (d.w_m <= 0 || d.h_m <= 0) throw NumberError("w_m, h_m: a defect needs a positive size");
  return d;
}

// What is wrong with a header's column names ("" when nothing): one of x_m and frame, and the four
// others, each once.
std::string column_problem(const std::vector<std::string>& names) {
  static const std::array<std::string_view, 6> known = {"x_m",  "frame", "z_m",
                                                        "side", "w_m",   "h_m"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (std::find(known.begin(), known.end(), names[i]) == known.end()) {
      return fmt::format("unknown column '{}' (expected x_m or frame, z_m, side, w_m, h_m)",
                         escape_for_message(names[i]));
    }
    if (std::count(names.begin(), names.end(), names[i]) > 1) {
      return fmt::format("column '{}' appears twice", names[i]);
    }
  }
  const auto has = [&](std::string_view n) {
    return std::find(names.begin(), names.end(), n) != names.end();
  };
  if (has("x_m") == has("frame")) return "needs exactly one of x_m and frame";
  for (std::string_view n : {"z_m", "side", "w_m", "h_m"}) {
    if (!has(n)) return fmt::format("has no {}", n);
  }
  return {};
}

std::vector<std::string> split_commas(std::string_view line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    std::string_view cell = line.substr(start, comma - start);
    while (!cell.empty() && (cell.front() == ' ' || cell.front() == '\t')) cell.remove_prefix(1);
    while (!cell.empty() && (cell.back() == ' ' || cell.back() == '\t' || cell.back() == '\r'))
      cell.remove_suffix(1);
    cells.emplace_back(cell);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return cells;
}

std::vector<Defect> read_csv(const std::string& text, const std::string& source,
                             const FrameSpacing& frames) {
  std::vector<Defect> defects;
  std::vector<std::string> columns;
  std::istringstream in(text);
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::vector<std::string> cells = split_commas(line);
    if (columns.empty()) {
      if (const std::string problem = column_problem(cells); !problem.empty()) {
        throw InputError(source, line_no, "header: " + problem);
      }
      columns = std::move(cells);
      continue;
    }
    if (cells.size() != columns.size()) {
      throw InputError(source, line_no,
                       fmt::format("expected {} fields (as the header) but found {}",
                                   columns.size(), cells.size()));
    }
    std::map<std::string, std::string> fields;
    for (std::size_t i = 0; i < cells.size(); ++i) fields[columns[i]] = cells[i];
    try {
      defects.push_back(defect_from(fields, frames, line_no, {}));
    } catch (const NumberError& e) {
      throw InputError(source, line_no, e.what());
    }
  }
  if (columns.empty()) {
    throw InputError(source, 0,
                     "no header: the first line names the columns (x_m or frame, z_m, side, w_m, "
                     "h_m)");
  }
  return defects;
}

std::vector<Defect> read_json(const std::string& text, const std::string& source,
                              const FrameSpacing& frames) {
  const nlohmann::json doc = io::parse_json_document(text, source, "a defects file");
  if (!doc.is_object() || !doc.contains("defects") || !doc["defects"].is_array()) {
    throw InputError(source, 0, "expected an object with an array \"defects\"");
  }
  std::vector<Defect> defects;
  const auto& list = doc["defects"];
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = fmt::format("defects[{}]", i);
    const auto& item = list[i];
    if (!item.is_object()) throw InputError(source, 0, where + ": expected an object");
    std::map<std::string, std::string> fields;
    std::vector<std::string> names;
    for (const auto& [key, value] : item.items()) {
      names.push_back(key);
      if (value.is_string()) {
        fields[key] = value.get<std::string>();
      } else if (value.is_number()) {
        fields[key] = fmt::format("{}", value.get<double>());
      } else {
        throw InputError(
            source, 0,
            fmt::format("{}.{}: expected a number or a string", where, escape_for_message(key)));
      }
    }
    if (const std::string problem = column_problem(names); !problem.empty()) {
      throw InputError(source, 0, fmt::format("{}: {}", where, problem));
    }
    try {
      defects.push_back(defect_from(fields, frames, 0, where));
    } catch (const NumberError& e) {
      throw InputError(source, 0, fmt::format("{}.{}", where, e.what()));
    }
  }
  return defects;
}

// Where the hull's grid sits in the ship frame.
struct GridFrame {
  double cell = kMaskCellSize;
  double x0 = 0;
  double z0 = 0;
  HullSide side = HullSide::starboard;
  const HullGeometry* unrolled = nullptr;  // the 3D surface of an unrolled hull
};

GridFrame frame_of(const HullMask& hull) {
  GridFrame f;
  if (const HullGeometry* g = hull.geometry()) {
    f.cell = g->cell_size;
    f.x0 = g->x0;
    f.z0 = g->z0;
    f.side = g->side;
    if (g->unrolled()) f.unrolled = g;
  }
  return f;
}

}  // namespace

std::vector<Defect> read_defects(const std::filesystem::path& path, const FrameSpacing& frames) {
  const std::string source = path.string();
  const std::string text = io::read_file(path, kMaxDefectFileBytes, "the defects file");
  if (path.extension() == ".json") return read_json(text, source, frames);
  return read_csv(text, source, frames);
}

CorrosionMap rasterise_defects(const std::vector<Defect>& defects, const std::string& source,
                               const HullMask& hull) {
  const GridFrame f = frame_of(hull);
  CorrosionMap map{source, grid::Grid<std::int8_t>(hull.width(), hull.height(), -1)};
  for (int i : hull.cells()) map.cells[i] = 0;
  // Grid column/row whose centre is nearest a ship-frame coordinate, unclipped.
  const auto column = [&](double x) { return (x - f.x0) / f.cell - 0.5; };
  const auto row = [&](double z) { return (z - f.z0) / f.cell - 0.5; };
  const auto fail = [&](const Defect& d, const std::string& problem) {
    if (d.line > 0) throw InputError(source, d.line, problem);
    throw InputError(source, 0, fmt::format("{}: {}", d.where, problem));
  };
  for (const Defect& d : defects) {
    if (f.unrolled) {
      // Rows by height as on a side; columns are the cells of the defect's side (port left of the
      // bow, starboard right) whose surface point lies in [x − w/2, x + w/2).
      const HullGeometry& g = *f.unrolled;
      int y_lo = static_cast<int>(std::ceil(row(d.z_m - d.h_m / 2)));
      int y_hi = static_cast<int>(std::ceil(row(d.z_m + d.h_m / 2))) - 1;
      if (y_lo > y_hi) y_lo = y_hi = static_cast<int>(std::lround(row(d.z_m)));
      const double half = std::max(d.w_m, f.cell) / 2;  // a point defect marks the nearest cell
      int marked = 0;
      for (int y = std::max(y_lo, 0); y <= std::min(y_hi, hull.height() - 1); ++y) {
        for (int x = 0; x < hull.width(); ++x) {
          const bool port_cell = g.centre_x(x) < 0;
          if (!hull.is_hull(x, y) || port_cell != (d.side == HullSide::port)) continue;
          const double sx = g.surface(x, y).x;
          if (sx < d.x_m - half || sx >= d.x_m + half) continue;
          map.cells(x, y) = 1;
          ++marked;
        }
      }
      if (marked == 0) {
        fail(d, fmt::format("the defect at x {:g} m, z {:g} m covers no hull cell on the {} side "
                            "of the unrolled hull (z spans {:g} … {:g} m)",
                            d.x_m, d.z_m, to_string(d.side), f.z0, f.z0 + hull.height() * f.cell));
      }
      continue;
    }
    if (d.side != f.side) {
      fail(d, fmt::format("the defect is on the {} side but the hull shows {}", to_string(d.side),
                          to_string(f.side)));
    }
    // Cells whose centre lies in [x − w/2, x + w/2) × [z − h/2, z + h/2).
    int x_lo = static_cast<int>(std::ceil(column(d.x_m - d.w_m / 2)));
    int x_hi = static_cast<int>(std::ceil(column(d.x_m + d.w_m / 2))) - 1;
    int y_lo = static_cast<int>(std::ceil(row(d.z_m - d.h_m / 2)));
    int y_hi = static_cast<int>(std::ceil(row(d.z_m + d.h_m / 2))) - 1;
    if (x_lo > x_hi) x_lo = x_hi = static_cast<int>(std::lround(column(d.x_m)));
    if (y_lo > y_hi) y_lo = y_hi = static_cast<int>(std::lround(row(d.z_m)));
    int marked = 0;
    for (int y = std::max(y_lo, 0); y <= std::min(y_hi, hull.height() - 1); ++y) {
      for (int x = std::max(x_lo, 0); x <= std::min(x_hi, hull.width() - 1); ++x) {
        if (!hull.is_hull(x, y)) continue;
        map.cells(x, y) = 1;
        ++marked;
      }
    }
    if (marked == 0) {
      fail(d, fmt::format("the defect at x {:g} m, z {:g} m covers no hull cell (the grid spans x "
                          "{:g} … {:g} m, z {:g} … {:g} m)",
                          d.x_m, d.z_m, f.x0, f.x0 + hull.width() * f.cell, f.z0,
                          f.z0 + hull.height() * f.cell));
    }
  }
  return map;
}

CorrosionMap load_defect_map(const std::filesystem::path& path, const HullMask& hull,
                             const FrameSpacing& frames) {
  return rasterise_defects(read_defects(path, frames), path.string(), hull);
}

}  // namespace hullinspect::world
