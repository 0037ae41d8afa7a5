// The unrolled hull (docs/hulls.md "The whole hull"): a closed mesh cut by horizontal planes; each
// cut is one closed outline, walked from the bow (its foremost point on the centre plane) toward
// port and toward starboard to the stern (its aftmost point on the centre plane). A column is an
// arc length along that outline, so 4-neighbours on the grid are neighbours on the surface; rows
// are heights. Each cell is sampled on a k × k lattice (k heights × k arc lengths) like the side
// projection; the surface area a sample stands for is (cell / k)² / |horizontal part of the
// normal|, which is how the cell-area error is measured.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <unordered_map>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/mesh_hull.hpp"

namespace hullinspect::world {

namespace {

constexpr int kSamples = 7;  // per cell side; odd so the centre sample is the cell's centre
constexpr double kInf = std::numeric_limits<double>::infinity();
/// A transom facet faces aft more than sideways (its horizontal normal within 45° of −x).
constexpr double kTransomCos = 0.7071;
/// 1/|horizontal normal| is capped here: a facet that is nearly horizontal where a cut crosses it
/// would otherwise stand for an unbounded area.
constexpr double kMinHorizontalNormal = 1e-3;
/// A second outline of a cut up to this fraction of the hull's is a lobe of the hull (see cut()).
constexpr double kMaxLobe = 0.1;

using Vec = std::array<double, 3>;

struct Facet {
  std::array<Vec, 3> p;
  std::array<int, 3> vertex;  // welded vertex ids
  Normal normal;
  double z_lo, z_hi;
};

/// One piece of a cut: from the crossing on edge `from` to the crossing on edge `to`, oriented so
/// that the outline runs counter-clockwise seen from above (starboard stern→bow, port bow→stern).
struct Segment {
  std::uint64_t from, to;
  double ax, ay, bx, by;
  int facet;
};

/// One cut at height z, as an outline measured from the bow.
struct Section {
  bool valid = false;
  std::vector<double> x, y, s;  // outline vertices and cumulative arc length (closed: s.back() = P)
  std::vector<int> facet;       // facet of the piece from vertex i to i + 1
  double perimeter = 0;
  double s_bow = 0;           // arc length of the bow point
  double port = 0, stbd = 0;  // arc length kept from the bow toward the stern on each side
};

/// Outlines left out as lobes, over all cuts.
struct Lobes {
  int count = 0;
  double z_lo = kInf, z_hi = -kInf, longest = 0, x = 0;
};

struct Sample {
  double x, y;
  int facet;
};

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

struct VertexHash {
  std::size_t operator()(const Vec& v) const {
    std::size_t h = 0;
    for (double d : v) {
      const double positive = d + 0.0;  // −0 and +0 are the same coordinate
      std::uint64_t bits;
      std::memcpy(&bits, &positive, sizeof bits);
      h = h * 1000003u ^ std::hash<std::uint64_t>{}(bits);
    }
    return h;
  }
};

Vec to_ship(const std::array<double, 3>& p, const MeshImportOptions& opt) {
  Vec s;
  for (std::size_t i = 0; i < 3; ++i) {
    s[i] = opt.scale * opt.axes.sign[i] * p[static_cast<std::size_t>(opt.axes.axis[i])];
  }
  return s;
}

class Unroller {
 public:
  Unroller(std::span<const MeshTriangle> triangles, const MeshImportOptions& opt,
           const std::string& source)
      : opt_(opt), source_(source) {
    const bool flip = opt.axes.determinant() < 0;  // a reflection reverses the winding
    std::unordered_map<Vec, int, VertexHash> ids;
    double y_min = kInf, y_max = -kInf;
    for (const MeshTriangle& tri : triangles) {
      Facet f{};
      for (std::size_t k = 0; k < 3; ++k) f.p[k] = to_ship(tri.v[k], opt);
      if (flip) std::swap(f.p[1], f.p[2]);
      for (const Vec& p : f.p) {
        if (!std::isfinite(p[0] + p[1] + p[2])) {
          throw InputError(source, 0, "a vertex is not a finite number");
        }
      }
      const Vec u{f.p[1][0] - f.p[0][0], f.p[1][1] - f.p[0][1], f.p[1][2] - f.p[0][2]};
      const Vec v{f.p[2][0] - f.p[0][0], f.p[2][1] - f.p[0][1], f.p[2][2] - f.p[0][2]};
      const Vec n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (!(len > 0)) continue;  // degenerate: no cut crosses it with a direction
      f.normal = Normal{static_cast<float>(n[0] / len), static_cast<float>(n[1] / len),
                        static_cast<float>(n[2] / len)};
      for (std::size_t k = 0; k < 3; ++k) {
        f.vertex[k] = ids.try_emplace(f.p[k], static_cast<int>(ids.size())).first->second;
        y_min = std::min(y_min, f.p[k][1]);
        y_max = std::max(y_max, f.p[k][1]);
      }
      f.z_lo = std::min({f.p[0][2], f.p[1][2], f.p[2][2]});
      f.z_hi = std::max({f.p[0][2], f.p[1][2], f.p[2][2]});
      z_min_ = std::min(z_min_, f.z_lo);
      z_max_ = std::max(z_max_, f.z_hi);
      facets_.push_back(f);
    }
    if (facets_.empty()) throw InputError(source, 0, "the mesh has no facet with an area");
    centre_y_ = (y_min + y_max) / 2;
    std::sort(facets_.begin(), facets_.end(),
              [](const Facet& a, const Facet& b) { return a.z_lo < b.z_lo; });
  }

  double z_min() const { return z_min_; }
  double z_max() const { return z_max_; }
  double centre_y() const { return centre_y_; }
  int facet_count() const { return static_cast<int>(facets_.size()); }
  const Lobes& lobes() const { return *lobes_; }
  const Facet& facet(int i) const { return facets_[static_cast<std::size_t>(i)]; }

  /// The cut at height z (invalid when no facet crosses it).
  Section cut(double z) const {
    std::vector<Segment> segments;
    for (std::size_t i = 0; i < facets_.size() && facets_[i].z_lo < z; ++i) {
      const Facet& f = facets_[i];
      if (f.z_hi < z) continue;
      // A vertex exactly at z counts as above: every facet then has 0 or 2 crossing edges.
      std::array<bool, 3> above{f.p[0][2] >= z, f.p[1][2] >= z, f.p[2][2] >= z};
      if (above[0] == above[1] && above[1] == above[2]) continue;
      // The crossing on the edge from vertex a to vertex b, interpolated from the lower vertex id
      // so that both facets on the edge get the same point.
      const auto crossing = [&](std::size_t a, std::size_t b, std::uint64_t& key, double& x,
                                double& y) {
        if (f.vertex[a] > f.vertex[b]) std::swap(a, b);
        const double t = (z - f.p[a][2]) / (f.p[b][2] - f.p[a][2]);
        x = f.p[a][0] + t * (f.p[b][0] - f.p[a][0]);
        y = f.p[a][1] + t * (f.p[b][1] - f.p[a][1]);
        key = edge_key(f.vertex[a], f.vertex[b]);
      };
      // The vertex alone on its side of the cut. The facets wind counter-clockwise seen from
      // outside, so the piece runs along ẑ × n (counter-clockwise seen from above) from the edge
      // after a lone vertex above to the edge before it (the other way round for one below):
      // decided by the winding, not by the points, which coincide when the cut passes a vertex.
      const std::size_t lone = above[0] == above[1] ? 2 : (above[0] == above[2] ? 1 : 0);
      const std::size_t next = (lone + 1) % 3, prev = (lone + 2) % 3;
      Segment seg{};
      if (above[lone]) {
        crossing(lone, next, seg.from, seg.ax, seg.ay);
        crossing(prev, lone, seg.to, seg.bx, seg.by);
      } else {
        crossing(prev, lone, seg.from, seg.ax, seg.ay);
        crossing(lone, next, seg.to, seg.bx, seg.by);
      }
      seg.facet = static_cast<int>(i);
      segments.push_back(seg);
    }
    if (segments.empty()) return {};
    cancel_fins(segments);
    if (segments.empty()) return {};
    return outline(segments, z);
  }

 private:
  /// Two pieces over the same edges in opposite directions are a zero-thickness fin (e.g. where
  /// both sides of a hull meet in the centre plane): they enclose nothing and are dropped.
  static void cancel_fins(std::vector<Segment>& segments) {
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> by_from;
    for (std::size_t i = 0; i < segments.size(); ++i) by_from[segments[i].from].push_back(i);
    std::vector<bool> dropped(segments.size(), false);
    for (std::size_t i = 0; i < segments.size(); ++i) {
      if (dropped[i]) continue;
      const auto it = by_from.find(segments[i].to);
      if (it == by_from.end()) continue;
      for (std::size_t j : it->second) {
        if (!dropped[j] && j != i && segments[j].to == segments[i].from) {
          dropped[i] = dropped[j] = true;
          break;
        }
      }
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < segments.size(); ++i) {
      if (!dropped[i]) segments[kept++] = segments[i];
    }
    segments.resize(kept);
  }

  Section outline(const std::vector<Segment>& segments, double z) const {
    std::unordered_map<std::uint64_t, std::size_t> next;
    for (std::size_t i = 0; i < segments.size(); ++i) {
      if (!next.emplace(segments[i].from, i).second) {
        throw InputError(
            source_, 0,
            fmt::format("the mesh is not one closed surface: at z = {:.3f} m an edge near x {:.2f} "
                        "m, y {:.2f} m joins more than two facets (--sides both needs a closed "
                        "hull)",
                        z, segments[i].ax, segments[i].ay));
      }
    }
    // Every closed outline of the cut; the hull is the longest.
    std::vector<std::vector<std::size_t>> loops;
    std::vector<double> lengths;
    std::vector<double> areas;  // signed: > 0 around a body, < 0 around a hole in one
    std::vector<bool> used(segments.size(), false);
    for (std::size_t first = 0; first < segments.size(); ++first) {
      if (used[first]) continue;
      std::vector<std::size_t> loop;
      double length = 0, area = 0;
      std::size_t current = first;
      do {
        const Segment& seg = segments[current];
        used[current] = true;
        loop.push_back(current);
        length += std::hypot(seg.bx - seg.ax, seg.by - seg.ay);
        area += (seg.ax * seg.by - seg.bx * seg.ay) / 2;
        const auto it = next.find(seg.to);
        if (it == next.end()) {
          throw InputError(source_, 0,
                           fmt::format("the mesh is not closed: its cut at z = {:.3f} m is open "
                                       "near x {:.2f} m, y {:.2f} m (--sides both needs a closed "
                                       "hull)",
                                       z, seg.bx, seg.by));
        }
        current = it->second;
      } while (current != first && !used[current]);
      // A hole (e.g. a tunnel through the hull) cannot be seen from outside: it is not unrolled.
      if (area < 0) continue;
      loops.push_back(std::move(loop));
      lengths.push_back(length);
      areas.push_back(area);
    }
    if (loops.empty()) return {};
    const auto longest = static_cast<std::size_t>(std::max_element(lengths.begin(), lengths.end()) -
                                                  lengths.begin());
    // An outline much shorter than the hull's is a lobe of the same body the cut separates (the
    // top of a bulbous bow below its notch): it is left out and reported. A longer one is another
    // body.
    bool other_body = false;
    for (std::size_t k = 0; k < loops.size(); ++k) {
      if (k == longest) continue;
      if (lengths[k] > kMaxLobe * lengths[longest]) {
        other_body = true;
        continue;
      }
      Lobes& l = *lobes_;
      l.count += 1;
      l.z_lo = std::min(l.z_lo, z);
      l.z_hi = std::max(l.z_hi, z);
      l.longest = std::max(l.longest, lengths[k]);
      l.x = segments[loops[k].front()].ax;
    }
    if (other_body) {
      std::string others;
      for (std::size_t k = 0; k < loops.size() && k < 6; ++k) {
        if (k == longest) continue;
        const Segment& seg = segments[loops[k].front()];
        others += fmt::format("{}{:.2f} m near x {:.2f} m, y {:.2f} m", others.empty() ? "" : "; ",
                              lengths[k], seg.ax, seg.ay);
      }
      throw InputError(source_, 0,
                       fmt::format("the mesh is not one body: its cut at z = {:.3f} m has {} "
                                   "outlines (besides the hull's {:.2f} m: {}); --sides both "
                                   "needs one closed hull",
                                   z, loops.size(), lengths[longest], others));
    }
    Section sec;
    for (std::size_t i : loops[longest]) {
      sec.x.push_back(segments[i].ax);
      sec.y.push_back(segments[i].ay);
      sec.facet.push_back(segments[i].facet);
    }
    sec.x.push_back(sec.x.front());
    sec.y.push_back(sec.y.front());
    sec.s.assign(sec.x.size(), 0.0);
    for (std::size_t i = 1; i < sec.x.size(); ++i) {
      sec.s[i] = sec.s[i - 1] + std::hypot(sec.x[i] - sec.x[i - 1], sec.y[i] - sec.y[i - 1]);
    }
    sec.perimeter = sec.s.back();
    if (!(sec.perimeter > 0)) return {};
    // The bow and the stern: the foremost and aftmost crossings of the centre plane.
    double bow_x = -kInf, stern_x = kInf, s_stern = 0;
    for (std::size_t i = 0; i + 1 < sec.x.size(); ++i) {
      const double y0 = sec.y[i] - centre_y_, y1 = sec.y[i + 1] - centre_y_;
      if ((y0 < 0) == (y1 < 0) && y0 != 0) continue;
      const double t = y0 == y1 ? 0.0 : y0 / (y0 - y1);
      const double x = sec.x[i] + t * (sec.x[i + 1] - sec.x[i]);
      const double s = sec.s[i] + t * (sec.s[i + 1] - sec.s[i]);
      if (x > bow_x) bow_x = x, sec.s_bow = s;
      if (x < stern_x) stern_x = x, s_stern = s;
    }
    if (!(bow_x > stern_x)) {
      throw InputError(source_, 0,
                       fmt::format("the mesh's cut at z = {:.3f} m does not cross the centre plane "
                                   "y = {:.3f} m at a bow and a stern (check --axes)",
                                   z, centre_y_));
    }
    sec.port = std::fmod(s_stern - sec.s_bow + sec.perimeter, sec.perimeter);
    sec.stbd = sec.perimeter - sec.port;
    if (!opt_.include_transom) {
      // Drop the transom: from the stern toward the bow, the pieces that face aft.
      const auto faces_aft = [&](double arc) {
        const Normal& n = facets_[static_cast<std::size_t>(at(sec, arc).facet)].normal;
        return n.x < -kTransomCos * std::hypot(double(n.x), double(n.y));
      };
      const double step = opt_.cell_size / kSamples;
      while (sec.port > 0 && faces_aft(-(sec.port - step / 2))) sec.port -= step;
      while (sec.stbd > 0 && faces_aft(sec.stbd - step / 2)) sec.stbd -= step;
      sec.port = std::max(sec.port, 0.0);
      sec.stbd = std::max(sec.stbd, 0.0);
    }
    sec.valid = true;
    return sec;
  }

 public:
  /// The outline's point at unrolled arc length u (negative: toward port from the bow).
  static Sample at(const Section& sec, double u) {
    // Port (u < 0) runs forward along the outline from the bow, starboard backward.
    double s = sec.s_bow - u;
    s = std::fmod(std::fmod(s, sec.perimeter) + sec.perimeter, sec.perimeter);
    const auto it = std::upper_bound(sec.s.begin(), sec.s.end(), s);
    std::size_t i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - sec.s.begin(), 1)) - 1;
    i = std::min(i, sec.facet.size() - 1);
    const double len = sec.s[i + 1] - sec.s[i];
    const double t = len > 0 ? (s - sec.s[i]) / len : 0.0;
    return {sec.x[i] + t * (sec.x[i + 1] - sec.x[i]), sec.y[i] + t * (sec.y[i + 1] - sec.y[i]),
            sec.facet[i]};
  }

 private:
  const MeshImportOptions& opt_;
  const std::string& source_;
  std::unique_ptr<Lobes> lobes_ = std::make_unique<Lobes>();  // filled by the const cut()
  std::vector<Facet> facets_;
  double z_min_ = kInf, z_max_ = -kInf;
  double centre_y_ = 0;
};

}  // namespace

MeshImport unroll_mesh(std::span<const MeshTriangle> triangles, const MeshImportOptions& opt,
                       const std::string& source) {
  opt.validate();
  const Unroller mesh(triangles, opt, source);
  const double c = opt.cell_size;
  const double z0 = opt.waterline ? *opt.waterline : mesh.z_min();
  const double hd = std::max(1.0, std::ceil((mesh.z_max() - z0) / c - 1e-9));
  if (!(mesh.z_max() > z0)) {
    throw InputError(source, 0, "no part of the mesh is above the waterline (check --waterline)");
  }
  if (hd > kMaxGridSide) {
    throw InputError(source, 0,
                     fmt::format("the unrolled hull is {:.0f} cells of {} m high; must be within "
                                 "1..{} (check --scale and --cell-size)",
                                 hd, c, kMaxGridSide));
  }
  const int height = static_cast<int>(hd);

  // Every cut first: the grid's width is the longest port and starboard arc over all heights.
  std::vector<Section> cuts(static_cast<std::size_t>(height) * kSamples);
  double port = 0, stbd = 0;
  for (int row = 0; row < height; ++row) {
    for (int j = 0; j < kSamples; ++j) {
      Section& sec = cuts[static_cast<std::size_t>(row * kSamples + j)];
      sec = mesh.cut(z0 + (row + (j + 0.5) / kSamples) * c);
      if (!sec.valid) continue;
      port = std::max(port, sec.port);
      stbd = std::max(stbd, sec.stbd);
    }
  }
  if (!(port + stbd > 0)) {
    throw InputError(source, 0, "no horizontal cut of the mesh has an outline (check --axes)");
  }
  // Column 0's left edge: a whole number of cells port of the bow, so the bow is a column edge.
  const double port_cells = std::max(1.0, std::ceil(port / c - 1e-9));
  const double wd = port_cells + std::max(1.0, std::ceil(stbd / c - 1e-9));
  if (wd > kMaxGridSide) {
    throw InputError(source, 0,
                     fmt::format("the unrolled hull is {:.0f} cells of {} m long; must be within "
                                 "1..{} (check --scale and --cell-size)",
                                 wd, c, kMaxGridSide));
  }
  const int width = static_cast<int>(wd);
  const double u0 = -port_cells * c;

  HullGeometry g = detail::empty_geometry(opt, source, u0, z0, width, height);
  g.side_plane_y = mesh.centre_y();
  // With the transom the cut is unrolled all round, so each row's two ends meet at the stern's
  // centre line: the grid closes on itself and a flight links the seam.
  g.seam = opt.include_transom && width >= 3;
  g.surface = grid::Grid<Point3>(width, height, Point3{});
  grid::Grid<std::uint8_t> is_hull(width, height, 0);
  grid::Grid<double> area(width, height, 0.0);  // surface area of the covered samples, m²

  const double sample_area = (c / kSamples) * (c / kSamples);
  const int centre = kSamples / 2;
  for (int row = 0; row < height; ++row) {
    for (int x = 0; x < width; ++x) {
      int covered = 0, best_distance = std::numeric_limits<int>::max();
      double cell_area = 0;
      Sample best{};
      double best_z = 0;
      for (int j = 0; j < kSamples; ++j) {
        const Section& sec = cuts[static_cast<std::size_t>(row * kSamples + j)];
        if (!sec.valid) continue;
        for (int i = 0; i < kSamples; ++i) {
          const double u = u0 + (x + (i + 0.5) / kSamples) * c;
          if (u < -sec.port || u > sec.stbd) continue;
          const Sample s = Unroller::at(sec, u);
          const Normal& n = mesh.facet(s.facet).normal;
          const double horizontal =
              std::max(kMinHorizontalNormal, std::hypot(double(n.x), double(n.y)));
          cell_area += sample_area / horizontal;
          ++covered;
          const int d = (i - centre) * (i - centre) + (j - centre) * (j - centre);
          if (d < best_distance) {
            best_distance = d;
            best = s;
            best_z = z0 + (row + (j + 0.5) / kSamples) * c;
          }
        }
      }
      if (covered == 0) continue;
      const double fraction = double(covered) / (kSamples * kSamples);
      g.coverage(x, row) = static_cast<float>(fraction);
      g.normal(x, row) = mesh.facet(best.facet).normal;
      g.surface(x, row) = Point3{static_cast<float>(best.x), static_cast<float>(best.y),
                                 static_cast<float>(best_z)};
      area(x, row) = cell_area;
      is_hull(x, row) = fraction + 1e-9 >= opt.min_coverage ? 1 : 0;
    }
  }

  MeshImport imported = detail::finish_import(std::move(is_hull), std::move(g), opt, source);
  imported.facets = static_cast<int>(triangles.size());
  imported.facing_facets = mesh.facet_count();
  if (const Lobes& l = mesh.lobes(); l.count > 0) {
    imported.warnings.push_back(fmt::format(
        "{}: {} cuts between z = {:.2f} and {:.2f} m have a small separate outline (up to {:.2f} m "
        "long, near x {:.2f} m) besides the hull's: those lobes are not unrolled",
        source, l.count, l.z_lo, l.z_hi, l.longest, l.x));
  }
  // The cell-area error: how much more surface a cell holds than the grid area it covers.
  const HullMask& hull = imported.hull;
  for (int i : hull.cells()) {
    const double grid_area = hull.geometry()->coverage[i] * c * c;
    const double error = area[i] / grid_area - 1;
    imported.surface_area += area[i];
    imported.mean_area_error += error;
    if (error > imported.worst_area_error || imported.worst_area_cell.x < 0) {
      imported.worst_area_error = error;
      imported.worst_area_cell = hull.mask().cell(i);
    }
  }
  imported.mean_area_error /= std::max(1, hull.cell_count());
  if (opt.max_area_error && imported.worst_area_error > *opt.max_area_error) {
    throw InputError(
        source, 0,
        fmt::format("the worst cell-area error is {:.1f} % at cell ({}, {}), above "
                    "--max-area-error {:g} (a fraction: raise it, or exclude steep surfaces with "
                    "--waterline)",
                    100 * imported.worst_area_error, imported.worst_area_cell.x,
                    imported.worst_area_cell.y, *opt.max_area_error));
  }
  return imported;
}

}  // namespace hullinspect::world
