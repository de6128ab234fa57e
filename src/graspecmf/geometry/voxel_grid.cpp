#include "graspecmf/geometry/voxel_grid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"

namespace graspecmf::geometry {

namespace {

constexpr int kMaxResolution = 1024;
constexpr double kMaxLines = 67108864.0;     // 2^26
constexpr double kMaxVoxels = 1073741824.0;  // 2^30

// A line's crossing of one triangle: height and winding change (+1 entering the solid upwards).
struct Hit {
  std::uint32_t line;
  double z;
  int sign;

  bool operator<(const Hit& o) const {
    if (line != o.line) return line < o.line;
    if (z != o.z) return z < o.z;
    return sign < o.sign;
  }
};

int sign_of(double v) {
  return (v > 0.0) - (v < 0.0);
}

// Which side of the projected edge lo → hi (lo, hi in canonical vertex order) the point (px, py)
// lies on: the sign of the 2-D cross product (hi − lo) × (p − lo), with an exact zero resolved by
// moving p to (px − ε, py − ε²). Zero only for an edge that projects to a point.
struct EdgeTest {
  double value;
  int sign;
};

EdgeTest edge_test(const Vec3& lo, const Vec3& hi, double px, double py) {
  const double dx = hi.x() - lo.x();
  const double dy = hi.y() - lo.y();
  const double value = dx * (py - lo.y()) - dy * (px - lo.x());
  if (value != 0.0) return {value, sign_of(value)};
  return {0.0, dy != 0.0 ? sign_of(dy) : sign_of(-dx)};
}

// The edge test of the directed edge u → v, always evaluated from the smaller vertex index so that
// the two triangles sharing an edge see exactly opposite results.
EdgeTest directed_edge_test(const TriangleMesh& mesh, std::uint32_t u, std::uint32_t v, double px,
                            double py) {
  if (u < v) return edge_test(mesh.vertices[u], mesh.vertices[v], px, py);
  const EdgeTest t = edge_test(mesh.vertices[v], mesh.vertices[u], px, py);
  return {-t.value, -t.sign};
}

// Index range [first, last] of the lines x0 + i·spacing that may lie in [lo, hi], widened by one
// on each side (the exact edge tests decide) and clamped to [0, n).
std::pair<int, int> line_range(double lo, double hi, double x0, double spacing, int n) {
  const double first = std::ceil((lo - x0) / spacing) - 1.0;
  const double last = std::floor((hi - x0) / spacing) + 1.0;
  return {static_cast<int>(std::max(first, 0.0)), static_cast<int>(std::min(last, n - 1.0))};
}

// Appends the crossing of line (px, py) with the triangle, if the line passes through it.
void add_hit(const TriangleMesh& mesh, const Triangle& tri, std::uint32_t line, double px,
             double py, std::vector<Hit>& hits) {
  // Test of the edge opposite each vertex: proportional to that vertex's barycentric weight.
  const EdgeTest ea = directed_edge_test(mesh, tri[1], tri[2], px, py);
  const EdgeTest eb = directed_edge_test(mesh, tri[2], tri[0], px, py);
  const EdgeTest ec = directed_edge_test(mesh, tri[0], tri[1], px, py);
  if (ea.sign == 0 || ea.sign != eb.sign || eb.sign != ec.sign) return;
  const double sum = ea.value + eb.value + ec.value;
  if (sum == 0.0) return;
  const double z = (ea.value * mesh.vertices[tri[0]].z() + eb.value * mesh.vertices[tri[1]].z() +
                    ec.value * mesh.vertices[tri[2]].z()) /
                   sum;
  // Counter-clockwise seen from above (+z normal) means leaving the solid on the way up.
  hits.push_back({line, z, -ea.sign});
}

// Crossings of every line with every triangle, sorted by line and height.
std::vector<Hit> line_hits(const TriangleMesh& mesh, const ColumnSpans& lines) {
  std::vector<Hit> hits;
  for (const Triangle& tri : mesh.triangles) {
    const Vec3& a = mesh.vertices[tri[0]];
    const Vec3& b = mesh.vertices[tri[1]];
    const Vec3& c = mesh.vertices[tri[2]];
    const auto [i0, i1] =
        line_range(std::min({a.x(), b.x(), c.x()}), std::max({a.x(), b.x(), c.x()}), lines.x0,
                   lines.spacing, lines.nx);
    const auto [j0, j1] =
        line_range(std::min({a.y(), b.y(), c.y()}), std::max({a.y(), b.y(), c.y()}), lines.y0,
                   lines.spacing, lines.ny);
    for (int j = j0; j <= j1; ++j) {
      const double py = lines.y0 + j * lines.spacing;
      for (int i = i0; i <= i1; ++i) {
        const double px = lines.x0 + i * lines.spacing;
        add_hit(mesh, tri, static_cast<std::uint32_t>(i + lines.nx * j), px, py, hits);
      }
    }
  }
  std::sort(hits.begin(), hits.end());
  return hits;
}

// The spans of every line from its sorted crossings: where the running sum of their signs (the
// winding number) is non-zero.
void collect_spans(const std::vector<Hit>& hits, ColumnSpans& lines) {
  const std::size_t num_lines = static_cast<std::size_t>(lines.nx) * lines.ny;
  lines.first.assign(num_lines + 1, 0);
  std::size_t next = 0;
  for (std::size_t line = 0; line < num_lines; ++line) {
    lines.first[line] = static_cast<std::uint32_t>(lines.spans.size());
    int winding = 0;
    double enter = 0.0;
    for (; next < hits.size() && hits[next].line == line; ++next) {
      const int before = winding;
      winding += hits[next].sign;
      if (before == 0 && winding != 0) enter = hits[next].z;
      if (before != 0 && winding == 0 && hits[next].z > enter) {
        lines.spans.push_back({enter, hits[next].z});
      }
    }
  }
  lines.first[num_lines] = static_cast<std::uint32_t>(lines.spans.size());
}

}  // namespace

bool ColumnSpans::inside(int i, int j, double z) const {
  const std::size_t line = static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * j;
  for (std::uint32_t s = first[line]; s < first[line + 1]; ++s) {
    if (z < spans[s][0]) return false;
    if (z < spans[s][1]) return true;
  }
  return false;
}

double ColumnSpans::inside_length(int i, int j, double lo, double hi) const {
  const std::size_t line = static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * j;
  double length = 0.0;
  for (std::uint32_t s = first[line]; s < first[line + 1]; ++s) {
    length += std::max(0.0, std::min(hi, spans[s][1]) - std::max(lo, spans[s][0]));
  }
  return length;
}

std::size_t VoxelGrid::count() const {
  return static_cast<std::size_t>(std::count(occupied.begin(), occupied.end(), std::uint8_t{1}));
}

double VoxelGrid::volume() const {
  return static_cast<double>(count()) * voxel_size * voxel_size * voxel_size;
}

ColumnSpans column_spans(const TriangleMesh& mesh, double x0, double y0, double spacing, int nx,
                         int ny) {
  if (!std::isfinite(spacing) || spacing <= 0.0 || !std::isfinite(x0) || !std::isfinite(y0)) {
    throw Error("column_spans: the spacing must be positive and finite, and the origin finite");
  }
  if (std::min(nx, ny) < 1 || static_cast<double>(nx) * ny > kMaxLines) {
    throw Error("column_spans: the lattice must have at least 1 and at most 2^26 lines");
  }
  require_watertight(mesh, "column_spans");
  ColumnSpans lines;
  lines.x0 = x0;
  lines.y0 = y0;
  lines.spacing = spacing;
  lines.nx = nx;
  lines.ny = ny;
  collect_spans(line_hits(mesh, lines), lines);
  return lines;
}

VoxelGrid fitted_grid(const BoundingBox& box, int resolution) {
  if (resolution < 1 || resolution > kMaxResolution) {
    throw Error("voxel grid: resolution " + std::to_string(resolution) + " is outside [1, " +
                std::to_string(kMaxResolution) + "]");
  }
  const double longest = box.extent().maxCoeff();
  if (!std::isfinite(longest) || longest <= 0.0) {
    throw Error("voxel grid: the bounding box has no extent");
  }
  VoxelGrid grid;
  grid.voxel_size = longest / resolution;
  for (int k = 0; k < 3; ++k) {
    grid.dims[k] =
        std::clamp(static_cast<int>(std::ceil(box.extent()[k] / grid.voxel_size)), 1, resolution);
  }
  grid.origin =
      box.center() - 0.5 * grid.voxel_size * Vec3(grid.dims[0], grid.dims[1], grid.dims[2]);
  return grid;
}

VoxelGrid voxelize(const TriangleMesh& mesh, int resolution) {
  validate_mesh(mesh, "voxelize");
  const VoxelGrid grid = fitted_grid(bounding_box(mesh), resolution);
  return voxelize(mesh, grid.origin, grid.voxel_size, grid.dims);
}

VoxelGrid voxelize(const TriangleMesh& mesh, const Vec3& origin, double voxel_size,
                   const std::array<int, 3>& dims) {
  if (!origin.allFinite() || std::min({dims[0], dims[1], dims[2]}) < 1 ||
      static_cast<double>(dims[0]) * dims[1] * dims[2] > kMaxVoxels) {
    throw Error("voxelize: the origin must be finite and the grid have 1 to 2^30 voxels");
  }
  const ColumnSpans lines =
      column_spans(mesh, origin.x() + 0.5 * voxel_size, origin.y() + 0.5 * voxel_size, voxel_size,
                   dims[0], dims[1]);
  VoxelGrid grid;
  grid.origin = origin;
  grid.voxel_size = voxel_size;
  grid.dims = dims;
  grid.occupied.resize(static_cast<std::size_t>(dims[0]) * dims[1] * dims[2]);
  for (int k = 0; k < dims[2]; ++k) {
    const double z = origin.z() + (k + 0.5) * voxel_size;
    for (int j = 0; j < dims[1]; ++j) {
      for (int i = 0; i < dims[0]; ++i) grid.occupied[grid.index(i, j, k)] = lines.inside(i, j, z);
    }
  }
  return grid;
}

}  // namespace graspecmf::geometry
