// Orthographic, depth-buffered projection of a mesh onto the ship's x–z plane (docs/model.md
// "Hulls from meshes"). Each cell is sampled on a k × k lattice (k odd, so one sample sits on the
// cell's centre); cell rows are rasterised one at a time, so memory is one row of samples whatever
// the grid size.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/grid/distance.hpp"
#include "hullinspect/world/mesh_hull.hpp"

namespace hullinspect::world {

namespace {

constexpr int kSamples = 7;  // per cell side; odd so the centre sample is the cell's centre
constexpr double kInf = std::numeric_limits<double>::infinity();

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// A facing facet in sample coordinates: u along x, v along z (sample (i, j) centred at (i, j)),
/// o how far out toward the viewer (−y from starboard, +y from port).
struct ProjectedFacet {
  double u[3], v[3], o[3];
  Normal normal;
  int row_first, row_last;  // cell rows it may cover
};

Vec to_ship(const std::array<double, 3>& p, const MeshImportOptions& opt) {
  Vec s;
  for (std::size_t i = 0; i < 3; ++i) {
    s[i] = opt.scale * opt.axes.sign[i] * p[static_cast<std::size_t>(opt.axes.axis[i])];
  }
  return s;
}

/// The x and z extent of the part of triangle t at or above z = floor (floor = −inf: all of it).
void extend_bounds(const std::array<Vec, 3>& t, double floor, double& x_min, double& x_max,
                   double& z_min, double& z_max) {
  const auto add = [&](double x, double z) {
    x_min = std::min(x_min, x);
    x_max = std::max(x_max, x);
    z_min = std::min(z_min, z);
    z_max = std::max(z_max, z);
  };
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec& a = t[k];
    const Vec& b = t[(k + 1) % 3];
    if (a[2] >= floor) add(a[0], a[2]);
    if ((a[2] < floor) != (b[2] < floor)) {  // the edge crosses the floor: add the crossing
      const double s = (floor - a[2]) / (b[2] - a[2]);
      add(a[0] + s * (b[0] - a[0]), floor);
    }
  }
}

std::string component_list(const std::vector<int>& sizes, const std::vector<grid::Cell>& first) {
  std::string parts;
  for (std::size_t k = 0; k < sizes.size() && k < 5; ++k) {
    parts +=
        fmt::format("{}{} cells from ({}, {})", k ? "; " : "", sizes[k], first[k].x, first[k].y);
  }
  if (sizes.size() > 5) parts += "; …";
  return parts;
}

}  // namespace

void MeshImportOptions::validate() const {
  if (!(cell_size > 0) || !std::isfinite(cell_size)) {
    throw ParameterError("cell-size", "expected a positive number of metres");
  }
  if (!(scale > 0) || !std::isfinite(scale)) throw ParameterError("scale", "expected a number > 0");
  if (!(min_coverage > 0 && min_coverage <= 1)) {
    throw ParameterError("min-coverage", "expected a fraction in (0, 1]");
  }
  if (waterline && !std::isfinite(*waterline)) {
    throw ParameterError("waterline", "expected a finite number of metres");
  }
  if (include_bottom) {
    throw ParameterError("include",
                         "bottom is not supported: a UAV standing off horizontally cannot see the "
                         "flat bottom (expected transom)");
  }
  if (include_transom && side != HullSide::both) {
    throw ParameterError("include", "transom needs --sides both (one side has no transom)");
  }
  if (max_area_error && !(*max_area_error >= 0 && std::isfinite(*max_area_error))) {
    throw ParameterError("max-area-error", "expected a fraction >= 0 (0.1 is 10 %)");
  }
  if (max_area_error && side != HullSide::both) {
    throw ParameterError("max-area-error", "needs --sides both (a side projection keeps areas)");
  }
}

MeshImport project_mesh(std::span<const MeshTriangle> triangles, const MeshImportOptions& opt,
                        const std::string& source) {
  opt.validate();
  if (opt.side == HullSide::both) return unroll_mesh(triangles, opt, source);
  const double out_sign = opt.side == HullSide::port ? 1.0 : -1.0;
  const bool flip = opt.axes.determinant() < 0;  // a reflection reverses the winding
  const double floor = opt.waterline ? *opt.waterline : -kInf;

  // Pass 1: the facing facets (ship frame) and the extent of their part above the waterline.
  std::vector<std::array<Vec, 3>> facing;
  std::vector<Normal> normals;
  double x_min = kInf, x_max = -kInf, z_min = kInf, z_max = -kInf;
  for (const MeshTriangle& tri : triangles) {
    std::array<Vec, 3> t{to_ship(tri.v[0], opt), to_ship(tri.v[1], opt), to_ship(tri.v[2], opt)};
    if (flip) std::swap(t[1], t[2]);
    bool finite = true;
    for (const Vec& p : t) finite = finite && std::isfinite(p[0] + p[1] + p[2]);
    if (!finite) throw InputError(source, 0, "a vertex is not a finite number");
    const Vec n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0) || !(n[1] * out_sign > 0)) continue;  // degenerate, edge-on or facing away
    if (t[0][2] < floor && t[1][2] < floor && t[2][2] < floor) continue;
    extend_bounds(t, floor, x_min, x_max, z_min, z_max);
    facing.push_back(t);
    normals.push_back(Normal{static_cast<float>(n[0] / len), static_cast<float>(n[1] / len),
                             static_cast<float>(n[2] / len)});
  }
  if (facing.empty()) {
    throw InputError(source, 0,
                     fmt::format("no facet faces the {} side{} (check --axes and --side)",
                                 to_string(opt.side), opt.waterline ? " above the waterline" : ""));
  }
  const double x0 = x_min;
  const double z0 = opt.waterline ? *opt.waterline : z_min;
  const double width_m = x_max - x0;
  const double height_m = z_max - z0;
  const auto cells = [&](double extent) {
    return std::max(1.0, std::ceil(extent / opt.cell_size - 1e-9));
  };
  const double wd = cells(width_m), hd = cells(height_m);
  if (wd > kMaxGridSide || hd > kMaxGridSide) {
    throw InputError(
        source, 0,
        fmt::format("the projection is {:.0f} × {:.0f} cells of {} m; each side must be "
                    "within 1..{} (check --scale and --cell-size)",
                    wd, hd, opt.cell_size, kMaxGridSide));
  }
  const int width = static_cast<int>(wd), height = static_cast<int>(hd);

  // Facets in sample coordinates, in order of their first row.
  const double per_sample = kSamples / opt.cell_size;
  std::vector<ProjectedFacet> facets;
  facets.reserve(facing.size());
  for (std::size_t f = 0; f < facing.size(); ++f) {
    ProjectedFacet p{};
    double v_min = kInf, v_max = -kInf;
    for (std::size_t k = 0; k < 3; ++k) {
      p.u[k] = (facing[f][k][0] - x0) * per_sample - 0.5;
      p.v[k] = (facing[f][k][2] - z0) * per_sample - 0.5;
      p.o[k] = out_sign * facing[f][k][1];
      v_min = std::min(v_min, p.v[k]);
      v_max = std::max(v_max, p.v[k]);
    }
    p.normal = normals[f];
    p.row_first = static_cast<int>(std::clamp(std::floor((v_min + 0.5) / kSamples), 0.0, hd - 1));
    p.row_last = static_cast<int>(std::clamp(std::floor((v_max + 0.5) / kSamples), 0.0, hd - 1));
    facets.push_back(p);
  }
  std::stable_sort(
      facets.begin(), facets.end(),
      [](const ProjectedFacet& a, const ProjectedFacet& b) { return a.row_first < b.row_first; });

  HullGeometry g = detail::empty_geometry(opt, source, x0, z0, width, height);
  g.normal = grid::Grid<Normal>(width, height, Normal{0, static_cast<float>(out_sign), 0});
  grid::Grid<double> outward(width, height, -kInf);  // o of the surface kept for each cell
  grid::Grid<std::uint8_t> is_hull(width, height, 0);

  // Pass 2: rasterise one cell row of samples at a time.
  const int row_samples = width * kSamples;
  std::vector<double> sample_o(static_cast<std::size_t>(row_samples) * kSamples);
  std::vector<int> sample_facet(sample_o.size());
  std::vector<int> active;
  std::size_t next = 0;
  const int centre = kSamples / 2;
  for (int row = 0; row < height; ++row) {
    while (next < facets.size() && facets[next].row_first == row) active.push_back(int(next++));
    std::fill(sample_o.begin(), sample_o.end(), -kInf);
    std::fill(sample_facet.begin(), sample_facet.end(), -1);
    const int j_begin = row * kSamples;
    for (int index : active) {
      const ProjectedFacet& p = facets[static_cast<std::size_t>(index)];
      const double area =
          (p.u[1] - p.u[0]) * (p.v[2] - p.v[0]) - (p.u[2] - p.u[0]) * (p.v[1] - p.v[0]);
      if (std::abs(area) < 1e-12) continue;
      const double inv = 1.0 / area;
      const double u_lo = std::min({p.u[0], p.u[1], p.u[2]}),
                   u_hi = std::max({p.u[0], p.u[1], p.u[2]});
      const double v_lo = std::min({p.v[0], p.v[1], p.v[2]}),
                   v_hi = std::max({p.v[0], p.v[1], p.v[2]});
      // Clamped in floating point first: a facet far below the waterline must not overflow int.
      const auto sample = [](double v, int lo, int hi) {
        return static_cast<int>(std::clamp(v, lo - 1.0, hi + 1.0));
      };
      const int i0 = std::max(0, sample(std::ceil(u_lo), 0, row_samples));
      const int i1 = std::min(row_samples - 1, sample(std::floor(u_hi), 0, row_samples));
      const int j0 = std::max(j_begin, sample(std::ceil(v_lo), j_begin, j_begin + kSamples));
      const int j1 =
          std::min(j_begin + kSamples - 1, sample(std::floor(v_hi), j_begin, j_begin + kSamples));
      for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
          // Barycentric weights, normalised by the signed area (either winding in u–v).
          const double w0 = ((p.u[1] - i) * (p.v[2] - j) - (p.u[2] - i) * (p.v[1] - j)) * inv;
          const double w1 = ((p.u[2] - i) * (p.v[0] - j) - (p.u[0] - i) * (p.v[2] - j)) * inv;
          const double w2 = 1.0 - w0 - w1;
          constexpr double kEdge = -1e-9;  // shared edges count for both facets
          if (w0 < kEdge || w1 < kEdge || w2 < kEdge) continue;
          const double o = w0 * p.o[0] + w1 * p.o[1] + w2 * p.o[2];
          const std::size_t s = static_cast<std::size_t>(j - j_begin) * row_samples + i;
          if (o > sample_o[s]) {
            sample_o[s] = o;
            sample_facet[s] = index;
          }
        }
      }
    }
    // Reduce the samples to cells: coverage, and the surface at the centre (else the nearest).
    for (int x = 0; x < width; ++x) {
      int covered = 0;
      std::size_t best = 0;
      double best_o = -kInf;
      for (int dj = 0; dj < kSamples; ++dj) {
        for (int di = 0; di < kSamples; ++di) {
          const std::size_t s = static_cast<std::size_t>(dj) * row_samples + x * kSamples + di;
          if (sample_facet[s] < 0) continue;
          ++covered;
          if (sample_o[s] > best_o) {
            best_o = sample_o[s];
            best = s;
          }
        }
      }
      if (covered == 0) continue;
      const std::size_t centre_sample =
          static_cast<std::size_t>(centre) * row_samples + x * kSamples + centre;
      if (sample_facet[centre_sample] >= 0) best = centre_sample;
      const double fraction = double(covered) / (kSamples * kSamples);
      g.coverage(x, row) = static_cast<float>(fraction);
      outward(x, row) = sample_o[best];
      g.normal(x, row) = facets[static_cast<std::size_t>(sample_facet[best])].normal;
      is_hull(x, row) = fraction + 1e-9 >= opt.min_coverage ? 1 : 0;
    }
    std::erase_if(
        active, [&](int index) { return facets[static_cast<std::size_t>(index)].row_last <= row; });
  }

  // The side plane passes through the innermost surface point; depth is measured out from it.
  double innermost = kInf;
  for (int i = 0; i < outward.size(); ++i) {
    if (outward[i] > -kInf) innermost = std::min(innermost, outward[i]);
  }
  g.side_plane_y = out_sign * innermost;
  for (int i = 0; i < outward.size(); ++i) {
    if (outward[i] > -kInf) g.depth[i] = static_cast<float>(outward[i] - innermost);
  }

  MeshImport imported = detail::finish_import(std::move(is_hull), std::move(g), opt, source);
  imported.facets = static_cast<int>(triangles.size());
  imported.facing_facets = static_cast<int>(facing.size());
  return imported;
}

namespace detail {

HullGeometry empty_geometry(const MeshImportOptions& opt, const std::string& source, double x0,
                            double z0, int width, int height) {
  HullGeometry g;
  g.cell_size = opt.cell_size;
  g.x0 = x0;
  g.z0 = z0;
  g.side = opt.side;
  g.axes = opt.axes;
  g.scale = opt.scale;
  g.waterline = opt.waterline;
  g.min_coverage = opt.min_coverage;
  g.mesh = source;
  g.depth = grid::Grid<float>(width, height, 0.0f);
  g.coverage = grid::Grid<float>(width, height, 0.0f);
  g.normal = grid::Grid<Normal>(width, height, Normal{0, -1, 0});
  return g;
}

MeshImport finish_import(grid::Grid<std::uint8_t> is_hull, HullGeometry g,
                         const MeshImportOptions& opt, const std::string& source) {
  std::vector<std::string> warnings;
  int hull_cells = 0;
  for (int i = 0; i < is_hull.size(); ++i) hull_cells += is_hull[i];
  if (hull_cells == 0) {
    throw InputError(source, 0,
                     fmt::format("no cell is at least {} covered (check --min-coverage and "
                                 "--cell-size)",
                                 opt.min_coverage));
  }
  grid::Grid<int> labels;
  grid::BfsScratch scratch;
  const int components = grid::label_components(is_hull, labels, scratch);
  if (components > 1) {
    std::vector<int> sizes(static_cast<std::size_t>(components), 0);
    std::vector<grid::Cell> first(static_cast<std::size_t>(components), {-1, -1});
    for (int i = 0; i < is_hull.size(); ++i) {
      if (!is_hull[i]) continue;
      const auto k = static_cast<std::size_t>(labels[i]);
      if (sizes[k]++ == 0) first[k] = is_hull.cell(i);
    }
    const std::string parts = component_list(sizes, first);
    if (!opt.keep_largest) {
      throw InputError(source, 0,
                       fmt::format("the projection is not 4-connected: {} components ({}); "
                                   "use --keep-largest to keep the largest",
                                   components, parts));
    }
    const auto largest =
        static_cast<int>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
    for (int i = 0; i < is_hull.size(); ++i) {
      if (is_hull[i] && labels[i] != largest) is_hull[i] = 0;
    }
    warnings.push_back(
        fmt::format("{}: the projection is not 4-connected: {} components ({}); kept the largest",
                    source, components, parts));
  }
  HullMask hull(std::move(is_hull), source);
  hull.attach_geometry(std::move(g));
  return MeshImport{std::move(hull), std::move(warnings)};
}

}  // namespace detail

}  // namespace hullinspect::world
