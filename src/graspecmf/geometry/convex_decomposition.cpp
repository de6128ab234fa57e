#include "graspecmf/geometry/convex_decomposition.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"
#include "graspecmf/geometry/voxel_grid.hpp"

namespace graspecmf::geometry {

namespace fs = std::filesystem;

namespace {

constexpr int kMinResolution = 4;
constexpr int kMaxResolution = 256;

using Index3 = std::array<int, 3>;

int sign_of(double v) {
  return (v > 0.0) - (v < 0.0);
}

// ---------------------------------------------------------------------------------------------
// Exact orientation: a floating-point determinant with Shewchuk's error bound, falling back to
// exact expansion arithmetic when the sign is uncertain.

// a + b = sum + error exactly (Knuth).
void two_sum(double a, double b, double& sum, double& error) {
  sum = a + b;
  const double b_virtual = sum - a;
  const double a_virtual = sum - b_virtual;
  error = (a - a_virtual) + (b - b_virtual);
}

// a × b = product + error exactly (barring underflow).
void two_product(double a, double b, double& product, double& error) {
  product = a * b;
  error = std::fma(a, b, -product);
}

// An exact sum of doubles, kept as a non-overlapping expansion ordered by increasing magnitude
// (Shewchuk's Grow-Expansion with zero elimination); its sign is that of the largest part.
class ExactSum {
 public:
  void add(double value) {
    std::size_t kept = 0;
    for (const double part : parts_) {
      double error = 0.0;
      two_sum(value, part, value, error);
      if (error != 0.0) parts_[kept++] = error;
    }
    parts_.resize(kept);
    if (value != 0.0) parts_.push_back(value);
  }
  int sign() const { return parts_.empty() ? 0 : sign_of(parts_.back()); }

 private:
  std::vector<double> parts_;
};

// Exact sign of det[u; v; w] for u = b − a, v = c − a, w = d − a: each difference is an exact
// two-term expansion, and the six products of the Leibniz formula are expanded term by term.
int orientation_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  std::array<std::array<std::array<double, 2>, 3>, 3> m{};  // m[row][column] = {high, low}
  const Vec3* rows[3] = {&b, &c, &d};
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) two_sum((*rows[r])[k], -a[k], m[r][k][0], m[r][k][1]);
  }
  static constexpr int kPermutations[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                              {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  ExactSum sum;
  for (int p = 0; p < 6; ++p) {
    const double sign = p < 3 ? 1.0 : -1.0;
    for (int bits = 0; bits < 8; ++bits) {
      const double x = m[0][kPermutations[p][0]][bits & 1];
      const double y = m[1][kPermutations[p][1]][(bits >> 1) & 1];
      const double z = m[2][kPermutations[p][2]][(bits >> 2) & 1];
      if (x == 0.0 || y == 0.0 || z == 0.0) continue;
      double xy = 0.0;
      double xy_error = 0.0;
      two_product(x, y, xy, xy_error);
      double terms[4];
      two_product(xy, z, terms[0], terms[1]);
      two_product(xy_error, z, terms[2], terms[3]);
      for (const double term : terms) sum.add(sign * term);
    }
  }
  return sum.sign();
}

}  // namespace

int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double ux = b.x() - a.x(), uy = b.y() - a.y(), uz = b.z() - a.z();
  const double vx = c.x() - a.x(), vy = c.y() - a.y(), vz = c.z() - a.z();
  const double wx = d.x() - a.x(), wy = d.y() - a.y(), wz = d.z() - a.z();
  const double vxwy = vx * wy, wxvy = wx * vy;
  const double wxuy = wx * uy, uxwy = ux * wy;
  const double uxvy = ux * vy, vxuy = vx * uy;
  const double det = uz * (vxwy - wxvy) + vz * (wxuy - uxwy) + wz * (uxvy - vxuy);
  const double permanent = (std::abs(vxwy) + std::abs(wxvy)) * std::abs(uz) +
                           (std::abs(wxuy) + std::abs(uxwy)) * std::abs(vz) +
                           (std::abs(uxvy) + std::abs(vxuy)) * std::abs(wz);
  // Shewchuk's bound (7 + 56ε)ε × permanent covers every rounding error of the expression above.
  constexpr double kErrorBound = 7.7715611723761027e-16;
  if (std::abs(det) > kErrorBound * permanent) return sign_of(det);
  if (permanent == 0.0) return 0;  // every product is exactly zero
  return orientation_exact(a, b, c, d);
}

namespace {

// ---------------------------------------------------------------------------------------------
// Quickhull with exact orientation tests: a point is outside a face only if it is strictly above
// its plane, so the visible faces always form a disc and the hull stays closed and convex.

class Quickhull {
 public:
  explicit Quickhull(const std::vector<Vec3>& points) : points_(points) {
    std::array<std::uint32_t, 4> simplex{};
    if (!initial_simplex(simplex)) return;
    start_simplex(simplex);
    for (std::uint32_t f = 0; f < faces_.size(); ++f) {
      if (faces_[f].alive && !faces_[f].outside.empty()) add_point(f);
    }
  }

  double volume() const {
    if (faces_.empty()) return 0.0;
    const Vec3& origin = points_[faces_.front().v[0]];
    double sum = 0.0;
    for (const Face& f : faces_) {
      if (!f.alive) continue;
      sum += (points_[f.v[0]] - origin)
                 .dot((points_[f.v[1]] - origin).cross(points_[f.v[2]] - origin));
    }
    return sum / 6.0;
  }

  // The hull's triangles, vertices numbered in order of first use.
  TriangleMesh mesh() const {
    TriangleMesh out;
    std::vector<std::uint32_t> vertex_of(points_.size(), ~std::uint32_t{0});
    for (const Face& f : faces_) {
      if (!f.alive) continue;
      Triangle tri{};
      for (int k = 0; k < 3; ++k) {
        if (vertex_of[f.v[k]] == ~std::uint32_t{0}) {
          vertex_of[f.v[k]] = static_cast<std::uint32_t>(out.vertices.size());
          out.vertices.push_back(points_[f.v[k]]);
        }
        tri[k] = vertex_of[f.v[k]];
      }
      out.triangles.push_back(tri);
    }
    return out;
  }

 private:
  struct Face {
    std::array<std::uint32_t, 3> v{};     // counter-clockwise seen from outside
    std::array<std::uint32_t, 3> next{};  // the face across edge v[i] → v[(i + 1) % 3]
    Vec3 normal = Vec3::Zero();           // (v1 − v0) × (v2 − v0): ranks outside points
    std::vector<std::uint32_t> outside;   // points strictly above this face, not yet added
    bool alive = true;
  };
  struct HorizonEdge {
    std::uint32_t face;  // visible face whose edge it is
    int edge;
  };

  bool above(const Face& f, std::uint32_t p) const {
    return orientation(points_[f.v[0]], points_[f.v[1]], points_[f.v[2]], points_[p]) > 0;
  }

  // Four points spanning a volume: the lowest point, the farthest from it, the farthest from
  // their line and the first of the farthest from their plane that is exactly off it.
  bool initial_simplex(std::array<std::uint32_t, 4>& s) const {
    if (points_.size() < 4) return false;
    const auto best = [&](const auto& score) {
      std::uint32_t arg = 0;
      for (std::uint32_t i = 1; i < points_.size(); ++i) {
        if (score(points_[i]) > score(points_[arg])) arg = i;
      }
      return arg;
    };
    s[0] = best([](const Vec3& p) { return -p.x(); });
    const Vec3 p0 = points_[s[0]];
    s[1] = best([&](const Vec3& p) { return (p - p0).squaredNorm(); });
    const Vec3 axis = points_[s[1]] - p0;
    s[2] = best([&](const Vec3& p) { return (p - p0).cross(axis).squaredNorm(); });
    const Vec3 normal = axis.cross(points_[s[2]] - p0);
    s[3] = best([&](const Vec3& p) { return std::abs(normal.dot(p - p0)); });
    for (std::uint32_t i = 0; orientation(p0, points_[s[1]], points_[s[2]], points_[s[3]]) == 0;
         ++i) {
      if (i == points_.size()) return false;
      s[3] = i;
    }
    return true;
  }

  std::uint32_t add_face(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    Face f;
    f.v = {a, b, c};
    f.normal = (points_[b] - points_[a]).cross(points_[c] - points_[a]);
    faces_.push_back(std::move(f));
    return static_cast<std::uint32_t>(faces_.size() - 1);
  }

  // Index of the edge b → a in face f (the twin of edge a → b).
  int twin_edge(std::uint32_t f, std::uint32_t a, std::uint32_t b) const {
    for (int k = 0; k < 3; ++k) {
      if (faces_[f].v[k] == b && faces_[f].v[(k + 1) % 3] == a) return k;
    }
    throw Error("convex_hull: broken face adjacency");
  }

  void start_simplex(std::array<std::uint32_t, 4> s) {
    if (orientation(points_[s[0]], points_[s[1]], points_[s[2]], points_[s[3]]) > 0) {
      std::swap(s[1], s[2]);  // the fourth point must lie below the first face
    }
    const std::array<std::array<std::uint32_t, 3>, 4> tetra = {
        {{s[0], s[1], s[2]}, {s[0], s[3], s[1]}, {s[1], s[3], s[2]}, {s[2], s[3], s[0]}}};
    for (const auto& t : tetra) add_face(t[0], t[1], t[2]);
    for (std::uint32_t f = 0; f < 4; ++f) {
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = faces_[f].v[k];
        const std::uint32_t b = faces_[f].v[(k + 1) % 3];
        for (std::uint32_t g = 0; g < 4; ++g) {
          for (int j = 0; j < 3; ++j) {
            if (faces_[g].v[j] == b && faces_[g].v[(j + 1) % 3] == a) faces_[f].next[k] = g;
          }
        }
      }
    }
    std::vector<std::uint32_t> rest;
    for (std::uint32_t i = 0; i < points_.size(); ++i) {
      if (std::find(s.begin(), s.end(), i) == s.end()) rest.push_back(i);
    }
    assign(rest, 0);
  }

  // Gives each point to the first face from `first` on that it lies strictly above; points above
  // none are inside the hull (or on it) and are dropped.
  void assign(const std::vector<std::uint32_t>& candidates, std::uint32_t first) {
    for (const std::uint32_t p : candidates) {
      for (std::uint32_t f = first; f < faces_.size(); ++f) {
        if (above(faces_[f], p)) {
          faces_[f].outside.push_back(p);
          break;
        }
      }
    }
  }

  // Depth-first walk over the faces visible from p, entering face f through edge `entry`; the
  // edges to invisible faces are collected in order around the horizon.
  void find_horizon(std::uint32_t f, int entry, std::uint32_t p) {
    visited_[f] = stamp_;
    visible_.push_back(f);
    for (int k = 0; k < 3; ++k) {
      const int e = (entry + k) % 3;
      const std::uint32_t g = faces_[f].next[e];
      if (visited_[g] == stamp_) continue;
      if (above(faces_[g], p)) {
        find_horizon(g, twin_edge(g, faces_[f].v[e], faces_[f].v[(e + 1) % 3]), p);
      } else {
        horizon_.push_back({f, e});
      }
    }
  }

  // Adds the point of face f's outside set farthest from its plane.
  void add_point(std::uint32_t f) {
    const Face& face = faces_[f];
    std::uint32_t p = face.outside.front();
    for (const std::uint32_t q : face.outside) {
      if (face.normal.dot(points_[q] - points_[p]) > 0.0) p = q;
    }
    ++stamp_;
    visited_.resize(faces_.size(), 0);
    visible_.clear();
    horizon_.clear();
    find_horizon(f, 0, p);

    std::vector<std::uint32_t> orphans;
    for (const std::uint32_t v : visible_) {
      for (const std::uint32_t q : faces_[v].outside) {
        if (q != p) orphans.push_back(q);
      }
      faces_[v].outside = {};
      faces_[v].alive = false;
    }
    const auto first = static_cast<std::uint32_t>(faces_.size());
    const auto n = static_cast<std::uint32_t>(horizon_.size());
    for (std::uint32_t k = 0; k < n; ++k) {
      const HorizonEdge edge = horizon_[k];
      const std::uint32_t a = faces_[edge.face].v[edge.edge];
      const std::uint32_t b = faces_[edge.face].v[(edge.edge + 1) % 3];
      const std::uint32_t outer = faces_[edge.face].next[edge.edge];
      const HorizonEdge following = horizon_[(k + 1) % n];
      if (faces_[following.face].v[following.edge] != b) {
        throw Error("convex_hull: the horizon is not a simple loop");
      }
      const std::uint32_t created = add_face(a, b, p);
      faces_[created].next = {outer, first + (k + 1) % n, first + (k + n - 1) % n};
      faces_[outer].next[twin_edge(outer, a, b)] = created;
    }
    assign(orphans, first);
  }

  const std::vector<Vec3>& points_;
  std::vector<Face> faces_;
  std::vector<std::uint32_t> visited_;  // stamp_ marks the faces visible from the current point
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> visible_;
  std::vector<HorizonEdge> horizon_;
};

// ---------------------------------------------------------------------------------------------
// The mesh surface inside a cell, as convex polygons (triangles clipped by the cell's planes).

struct Polygons {
  std::vector<Vec3> points;
  std::vector<std::uint32_t> ends;  // polygon p is points[ends[p − 1], ends[p])

  void close_polygon(std::size_t first) {
    if (points.size() - first >= 3) {
      ends.push_back(static_cast<std::uint32_t>(points.size()));
    } else {
      points.resize(first);  // a touching edge or vertex holds no surface
    }
  }
  void append(const Vec3* polygon, std::size_t n) {
    const std::size_t first = points.size();
    points.insert(points.end(), polygon, polygon + n);
    close_polygon(first);
  }
};

// Calls visit(first point, point count) for every polygon.
template <typename Visit>
void for_each_polygon(const Polygons& polygons, Visit&& visit) {
  std::uint32_t start = 0;
  for (const std::uint32_t end : polygons.ends) {
    visit(polygons.points.data() + start, static_cast<std::size_t>(end - start));
    start = end;
  }
}

Polygons mesh_polygons(const TriangleMesh& mesh) {
  Polygons out;
  for (const Triangle& tri : mesh.triangles) {
    const Vec3 corners[3] = {mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]};
    out.append(corners, 3);
  }
  return out;
}

// Where edge a–b crosses the plane x[axis] = c (they lie strictly on either side), computed from
// the lower end so that both polygons sharing the edge get the same point.
Vec3 crossing(const Vec3& a, const Vec3& b, int axis, double c) {
  const Vec3& lo = a[axis] < b[axis] ? a : b;
  const Vec3& hi = a[axis] < b[axis] ? b : a;
  Vec3 x = lo + ((c - lo[axis]) / (hi[axis] - lo[axis])) * (hi - lo);
  x[axis] = c;
  return x;
}

// True if every point of the polygon has coordinate c along axis.
bool lies_in_plane(const Vec3* polygon, std::size_t n, int axis, double c) {
  return std::all_of(polygon, polygon + n, [&](const Vec3& p) { return p[axis] == c; });
}

// Component `axis` of the polygon's (Newell) normal.
double normal_component(const Vec3* polygon, std::size_t n, int axis) {
  Vec3 normal = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) normal += polygon[i].cross(polygon[(i + 1) % n]);
  return normal[axis];
}

// Clips one polygon to x[axis] ≤ c (below) and x[axis] ≥ c (above). A polygon lying in the plane
// goes to the side its solid is on (outward normal towards +axis: below).
void split_polygon(const Vec3* polygon, std::size_t n, int axis, double c, Polygons& below,
                   Polygons& above) {
  if (lies_in_plane(polygon, n, axis, c)) {
    (normal_component(polygon, n, axis) > 0.0 ? below : above).append(polygon, n);
    return;
  }
  const std::size_t first_below = below.points.size();
  const std::size_t first_above = above.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = polygon[i];
    const Vec3& b = polygon[(i + 1) % n];
    if (a[axis] <= c) below.points.push_back(a);
    if (a[axis] >= c) above.points.push_back(a);
    if ((a[axis] < c && b[axis] > c) || (a[axis] > c && b[axis] < c)) {
      const Vec3 x = crossing(a, b, axis, c);
      below.points.push_back(x);
      above.points.push_back(x);
    }
  }
  below.close_polygon(first_below);
  above.close_polygon(first_above);
}

std::pair<Polygons, Polygons> split_polygons(const Polygons& polygons, int axis, double c) {
  std::pair<Polygons, Polygons> out;
  for_each_polygon(polygons, [&](const Vec3* polygon, std::size_t n) {
    split_polygon(polygon, n, axis, c, out.first, out.second);
  });
  return out;
}

// ---------------------------------------------------------------------------------------------
// Phase 1: recursive splitting of the lattice's box into cells.

// A box of the lattice, [lo, hi] in plane indices, with the solid inside it.
struct Cell {
  Index3 lo{};
  Index3 hi{};
  Polygons surface;          // the mesh surface clipped to the box
  std::vector<Vec3> points;  // hull input: surface points and box corners inside the solid
  std::vector<Vec3> hull_vertices;
  double hull_volume = 0.0;
  double solid_volume = 0.0;
  bool splittable = true;

  // How much the hull overfills the solid.
  double excess() const { return hull_volume - solid_volume; }
};

// A candidate cut and the two cells it makes.
struct Split {
  int axis = 0;
  int index = 0;
  double gain = 0.0;  // parent excess − children's excess
  std::pair<Cell, Cell> children;
};

// Lowest and highest coordinate of the points along axis.
std::pair<double, double> extent(const std::vector<Vec3>& points, int axis) {
  const auto [lo, hi] =
      std::minmax_element(points.begin(), points.end(),
                          [&](const Vec3& a, const Vec3& b) { return a[axis] < b[axis]; });
  return {(*lo)[axis], (*hi)[axis]};
}

// A cut with less gain than this fraction of the cell's excess is no better than an arbitrary
// one: the first cut of a ring (a cup's wall) gains nothing whichever way it goes, only the
// second does; the cell is then halved across its longest side instead.
constexpr double kMinGain = 0.1;
// Phase 1 stops at this many cells per allowed part.
constexpr std::size_t kCellsPerPart = 4;

class Splitter {
 public:
  Splitter(const TriangleMesh& mesh, const DecompositionOptions& options, double tolerance)
      : options_(options), tolerance_(tolerance) {
    const VoxelGrid grid = fitted_grid(bounding_box(mesh), options.resolution);
    spacing_ = grid.voxel_size;
    dims_ = grid.dims;
    origin_ = grid.origin;
    lines_ = column_spans(mesh, origin_.x(), origin_.y(), spacing_, dims_[0] + 1, dims_[1] + 1);
    root_ = make_cell({0, 0, 0}, dims_, mesh_polygons(mesh));
  }

  // Splits the cell with the largest excess until every excess is within the tolerance, no cell
  // can be split, or there are kCellsPerPart × max_parts cells. Cells without solid are dropped.
  std::vector<Cell> run() const {
    std::vector<Cell> cells = {root_};
    const std::size_t budget = kCellsPerPart * static_cast<std::size_t>(options_.max_parts);
    while (cells.size() < budget) {
      const auto worst = most_concave(cells);
      if (worst == cells.end() || worst->excess() <= tolerance_) break;
      std::optional<std::pair<Cell, Cell>> children = split(*worst);
      if (!children) {
        worst->splittable = false;
        continue;
      }
      const auto at = cells.erase(worst);
      std::vector<Cell> kept;
      for (Cell* child : {&children->first, &children->second}) {
        if (!child->points.empty()) kept.push_back(std::move(*child));
      }
      cells.insert(at, std::make_move_iterator(kept.begin()), std::make_move_iterator(kept.end()));
    }
    return cells;
  }

 private:
  double plane(int axis, int index) const { return origin_[axis] + index * spacing_; }

  static std::vector<Cell>::iterator most_concave(std::vector<Cell>& cells) {
    auto worst = cells.end();
    for (auto it = cells.begin(); it != cells.end(); ++it) {
      if (it->splittable && (worst == cells.end() || it->excess() > worst->excess())) worst = it;
    }
    return worst;
  }

  Cell make_cell(const Index3& lo, const Index3& hi, Polygons surface) const {
    Cell cell;
    cell.lo = lo;
    cell.hi = hi;
    cell.surface = std::move(surface);
    cell.points = cell.surface.points;
    for (int corner = 0; corner < 8; ++corner) {
      const Index3 c = {(corner & 1) ? hi[0] : lo[0], (corner & 2) ? hi[1] : lo[1],
                        (corner & 4) ? hi[2] : lo[2]};
      if (lines_.inside(c[0], c[1], plane(2, c[2]))) {
        cell.points.emplace_back(plane(0, c[0]), plane(1, c[1]), plane(2, c[2]));
      }
    }
    std::sort(cell.points.begin(), cell.points.end(), [](const Vec3& a, const Vec3& b) {
      return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    });
    cell.points.erase(std::unique(cell.points.begin(), cell.points.end()), cell.points.end());
    const Quickhull hull(cell.points);
    cell.hull_vertices = hull.mesh().vertices;
    cell.hull_volume = hull.volume();
    cell.solid_volume = solid_volume(cell);
    return cell;
  }

  // Exact volume of the solid in the cell [X0, X1] × [Y0, Y1] × [Z0, Z1]: the flux of the field
  // (x − X0, 0, 0) out of it. Only the clipped surface and the cap on x = X1 contribute; the cap's
  // area is ∮ (y − Y0) dz around it: along the cut segments (the surface polygons' edges in that
  // plane, reversed) and up the part of the cell edge x = X1, y = Y1 inside the solid. Polygons in
  // the planes x = X1 or y = Y1 count as outside (the cell is shrunk by an infinitesimal), as does
  // the edge line, whose spans are taken at (X1 − ε, Y1 − ε²).
  double solid_volume(const Cell& cell) const {
    const double x0 = plane(0, cell.lo[0]);
    const double x1 = plane(0, cell.hi[0]);
    const double y0 = plane(1, cell.lo[1]);
    const double y1 = plane(1, cell.hi[1]);
    double flux = 0.0;
    double cap = (y1 - y0) * lines_.inside_length(cell.hi[0], cell.hi[1], plane(2, cell.lo[2]),
                                                  plane(2, cell.hi[2]));
    for_each_polygon(cell.surface, [&](const Vec3* polygon, std::size_t n) {
      if (lies_in_plane(polygon, n, 0, x1) || lies_in_plane(polygon, n, 1, y1)) return;
      for (std::size_t i = 1; i + 1 < n; ++i) {
        const Vec3 area = 0.5 * (polygon[i] - polygon[0]).cross(polygon[i + 1] - polygon[0]);
        flux += area.x() * ((polygon[0].x() + polygon[i].x() + polygon[i + 1].x()) / 3.0 - x0);
      }
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3& a = polygon[i];
        const Vec3& b = polygon[(i + 1) % n];
        if (a.x() == x1 && b.x() == x1) cap -= (0.5 * (a.y() + b.y()) - y0) * (b.z() - a.z());
      }
    });
    return flux + (x1 - x0) * cap;
  }

  // The lattice planes strictly between the cell's extreme points along axis: [first, last].
  std::pair<int, int> plane_range(const Cell& cell, int axis) const {
    const auto [lo, hi] = extent(cell.points, axis);
    int first = cell.lo[axis] + 1;
    int last = cell.hi[axis] - 1;
    while (first <= last && plane(axis, first) <= lo) ++first;
    while (first <= last && plane(axis, last) >= hi) --last;
    return {first, last};
  }

  Split split_at(const Cell& cell, int axis, int index) const {
    auto [below, above] = split_polygons(cell.surface, axis, plane(axis, index));
    Index3 below_hi = cell.hi;
    Index3 above_lo = cell.lo;
    below_hi[axis] = index;
    above_lo[axis] = index;
    Split split{axis,
                index,
                0.0,
                {make_cell(cell.lo, below_hi, std::move(below)),
                 make_cell(above_lo, cell.hi, std::move(above))}};
    split.gain = cell.excess() - split.children.first.excess() - split.children.second.excess();
    return split;
  }

  // The cut with the most gain: planes_per_axis evenly spaced interior planes per axis, then a
  // bisection search around the best on its axis. None if the cell has no plane strictly inside.
  std::optional<Split> best_cut(const Cell& cell) const {
    std::optional<Split> best;
    const auto consider = [&](int axis, int index) {
      Split split = split_at(cell, axis, index);
      if (!best || split.gain > best->gain) best = std::move(split);
    };
    const int coarse = options_.planes_per_axis;
    std::array<std::pair<int, int>, 3> ranges;
    for (int axis = 0; axis < 3; ++axis) {
      ranges[axis] = plane_range(cell, axis);
      const auto [first, last] = ranges[axis];
      const int count = last - first + 1;
      if (count <= coarse) {
        for (int index = first; index <= last; ++index) consider(axis, index);
      } else {
        for (int j = 1; j <= coarse; ++j)
          consider(axis, first + j * (count + 1) / (coarse + 1) - 1);
      }
    }
    if (!best) return std::nullopt;
    const int axis = best->axis;
    const auto [first, last] = ranges[axis];
    for (int step = (last - first + 1) / (2 * (coarse + 1)); step >= 1; step /= 2) {
      const int centre = best->index;
      if (centre - step >= first) consider(axis, centre - step);
      if (centre + step <= last) consider(axis, centre + step);
    }
    return best;
  }

  // The cell halved at the middle plane of its points' longest side that has a plane inside.
  std::pair<Cell, Cell> halve(const Cell& cell) const {
    int axis = -1;
    double longest = 0.0;
    for (int k = 0; k < 3; ++k) {
      const auto [first, last] = plane_range(cell, k);
      const auto [lo, hi] = extent(cell.points, k);
      if (first <= last && (axis < 0 || hi - lo > longest)) {
        axis = k;
        longest = hi - lo;
      }
    }
    const auto [first, last] = plane_range(cell, axis);
    return std::move(split_at(cell, axis, (first + last) / 2).children);
  }

  std::optional<std::pair<Cell, Cell>> split(const Cell& cell) const {
    std::optional<Split> best = best_cut(cell);
    if (!best) return std::nullopt;
    if (best->gain < kMinGain * cell.excess()) return halve(cell);
    return std::move(best->children);
  }

  DecompositionOptions options_;
  double tolerance_;
  double spacing_ = 0.0;
  Index3 dims_{};
  Vec3 origin_ = Vec3::Zero();
  ColumnSpans lines_;  // the lattice's vertical lines: cell corners and edges inside the solid
  Cell root_;
};

// ---------------------------------------------------------------------------------------------
// Phase 2: greedy merging of neighbouring cells.

// Cells merged so far: their solid's hull.
struct Group {
  std::vector<Vec3> points;  // hull vertices
  double hull_volume = 0.0;
  double solid_volume = 0.0;
  bool alive = true;
};

Group make_group(const std::vector<Vec3>& points, double solid_volume) {
  const Quickhull hull(points);
  return {hull.mesh().vertices, hull.volume(), solid_volume, true};
}

// Two neighbouring groups and their merger, ranked by the hull volume the merger adds.
struct Merger {
  std::size_t a;
  std::size_t b;
  double added_volume;
  Group merged;
};

Merger make_merger(const std::vector<Group>& groups, std::size_t a, std::size_t b) {
  std::vector<Vec3> points = groups[a].points;
  points.insert(points.end(), groups[b].points.begin(), groups[b].points.end());
  Group merged = make_group(points, groups[a].solid_volume + groups[b].solid_volume);
  const double added = merged.hull_volume - groups[a].hull_volume - groups[b].hull_volume;
  return {a, b, added, std::move(merged)};
}

// True if the boxes share part of a face.
bool touching(const Cell& a, const Cell& b) {
  for (int k = 0; k < 3; ++k) {
    if (a.hi[k] != b.lo[k] && b.hi[k] != a.lo[k]) continue;
    bool overlap = true;
    for (int j = 0; j < 3; ++j) {
      if (j != k) overlap = overlap && a.lo[j] < b.hi[j] && b.lo[j] < a.hi[j];
    }
    if (overlap) return true;
  }
  return false;
}

// Replaces the merger's two groups by their union: the mergers that involved them are dropped and
// the union's mergers with their neighbours added.
void apply_merger(Merger chosen, std::vector<Group>& groups, std::vector<Merger>& mergers) {
  groups[chosen.a].alive = false;
  groups[chosen.b].alive = false;
  groups.push_back(std::move(chosen.merged));
  const std::size_t united = groups.size() - 1;
  std::vector<std::size_t> neighbours;
  std::vector<Merger> kept;
  for (Merger& m : mergers) {
    const bool with_a = m.a == chosen.a || m.b == chosen.a;
    const bool with_b = m.a == chosen.b || m.b == chosen.b;
    if (!with_a && !with_b) {
      kept.push_back(std::move(m));
      continue;
    }
    const std::size_t other = (m.a == chosen.a || m.a == chosen.b) ? m.b : m.a;
    if (other != chosen.a && other != chosen.b) neighbours.push_back(other);
  }
  std::sort(neighbours.begin(), neighbours.end());
  neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  for (const std::size_t n : neighbours) kept.push_back(make_merger(groups, n, united));
  mergers = std::move(kept);
}

// Mergers of every two live groups, or only of those whose cells touch (group i is cell i).
std::vector<Merger> initial_mergers(const std::vector<Group>& groups,
                                    const std::vector<Cell>& cells, bool touching_only) {
  std::vector<Merger> mergers;
  for (std::size_t a = 0; a < groups.size(); ++a) {
    for (std::size_t b = a + 1; b < groups.size(); ++b) {
      if (!groups[a].alive || !groups[b].alive) continue;
      if (!touching_only || touching(cells[a], cells[b]))
        mergers.push_back(make_merger(groups, a, b));
    }
  }
  return mergers;
}

// Merges groups of cells, the cheapest merger (least added hull volume) first, while there are
// more than max_parts groups or the merged group's excess stays within the tolerance. Only
// touching groups merge, unless no such pair is left and there are still too many groups.
std::vector<Group> merge(const std::vector<Cell>& cells, std::size_t max_parts, double tolerance) {
  std::vector<Group> groups;
  for (const Cell& cell : cells) {
    groups.push_back({cell.hull_vertices, cell.hull_volume, cell.solid_volume, true});
  }
  std::vector<Merger> mergers = initial_mergers(groups, cells, true);
  for (std::size_t count = groups.size(); count > 1; --count) {
    if (mergers.empty()) {
      if (count <= max_parts) break;
      mergers = initial_mergers(groups, cells, false);
    }
    const auto cheapest = std::min_element(
        mergers.begin(), mergers.end(),
        [](const Merger& x, const Merger& y) { return x.added_volume < y.added_volume; });
    const double excess = cheapest->merged.hull_volume - cheapest->merged.solid_volume;
    if (count <= max_parts && excess > tolerance) break;
    apply_merger(std::move(*cheapest), groups, mergers);
  }
  groups.erase(
      std::remove_if(groups.begin(), groups.end(), [](const Group& g) { return !g.alive; }),
      groups.end());
  return groups;
}

void check_closed(const TriangleMesh& mesh) {
  validate_mesh(mesh, "convex_decomposition");
  const MeshTopology topology = analyze_topology(mesh);
  if (!topology.watertight) {
    throw Error("convex_decomposition: the mesh is not watertight (" +
                std::to_string(topology.num_boundary_edges) + " boundary and " +
                std::to_string(topology.num_nonmanifold_edges) + " non-manifold edges)");
  }
}

void check_options(const DecompositionOptions& options) {
  if (options.resolution < kMinResolution || options.resolution > kMaxResolution) {
    throw Error("convex_decomposition: resolution " + std::to_string(options.resolution) +
                " is outside [" + std::to_string(kMinResolution) + ", " +
                std::to_string(kMaxResolution) + "]");
  }
  if (options.max_parts < 1 || options.planes_per_axis < 1) {
    throw Error("convex_decomposition: max_parts and planes_per_axis must be at least 1");
  }
  if (!std::isfinite(options.concavity) || options.concavity < 0.0) {
    throw Error("convex_decomposition: concavity must be finite and non-negative");
  }
}

// ---------------------------------------------------------------------------------------------
// Disk cache: one binary file per decomposition.
//
// Layout (native byte order): the 8-byte magic, u64 part count, then per part u64 vertex count,
// u64 triangle count, 3 doubles per vertex, 3 u32 per triangle; finally the u64 FNV-1a hash of all
// bytes before it.

constexpr char kMagic[8] = {'G', 'C', 'V', 'X', 'D', 'E', 'C', '1'};
constexpr std::size_t kVertexBytes = 3 * sizeof(double);
// Bump when the algorithm's output changes, so that old cache files are no longer found.
constexpr std::uint64_t kAlgorithmVersion = 1;

class Fnv1a {
 public:
  void add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash_ = (hash_ ^ bytes[i]) * 1099511628211ULL;
  }
  template <typename T>
  void add_value(const T& value) {
    add(&value, sizeof value);
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ULL;
};

std::uint64_t cache_key(const TriangleMesh& mesh, const DecompositionOptions& options) {
  Fnv1a hash;
  hash.add(kMagic, sizeof kMagic);
  hash.add_value(kAlgorithmVersion);
  hash.add_value(static_cast<std::uint64_t>(mesh.vertices.size()));
  for (const Vec3& v : mesh.vertices) hash.add(v.data(), kVertexBytes);
  hash.add_value(static_cast<std::uint64_t>(mesh.triangles.size()));
  for (const Triangle& t : mesh.triangles) hash.add(t.data(), sizeof t);
  hash.add_value(options.resolution);
  hash.add_value(options.max_parts);
  hash.add_value(options.concavity);
  hash.add_value(options.planes_per_axis);
  return hash.value();
}

template <typename T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

std::string serialize(const std::vector<TriangleMesh>& parts) {
  std::string out(kMagic, sizeof kMagic);
  put(out, static_cast<std::uint64_t>(parts.size()));
  for (const TriangleMesh& part : parts) {
    put(out, static_cast<std::uint64_t>(part.vertices.size()));
    put(out, static_cast<std::uint64_t>(part.triangles.size()));
    for (const Vec3& v : part.vertices) {
      out.append(reinterpret_cast<const char*>(v.data()), kVertexBytes);
    }
    for (const Triangle& t : part.triangles) put(out, t);
  }
  Fnv1a hash;
  hash.add(out.data(), out.size());
  put(out, hash.value());
  return out;
}

// Reads fixed-size values from a byte string; false once a read would run past the end.
class ByteReader {
 public:
  ByteReader(const std::string& bytes, std::size_t end) : bytes_(bytes), end_(end) {}
  template <typename T>
  bool get(T& value) {
    if (end_ - pos_ < sizeof value) return false;
    std::memcpy(&value, bytes_.data() + pos_, sizeof value);
    pos_ += sizeof value;
    return true;
  }
  std::size_t left() const { return end_ - pos_; }

 private:
  const std::string& bytes_;
  std::size_t end_;
  std::size_t pos_ = 0;
};

bool read_part(ByteReader& in, TriangleMesh& part) {
  std::uint64_t num_vertices = 0;
  std::uint64_t num_triangles = 0;
  if (!in.get(num_vertices) || !in.get(num_triangles)) return false;
  if (num_vertices > in.left() / kVertexBytes || num_triangles > in.left() / sizeof(Triangle)) {
    return false;
  }
  part.vertices.resize(num_vertices);
  part.triangles.resize(num_triangles);
  for (Vec3& v : part.vertices) {
    if (!in.get(v.x()) || !in.get(v.y()) || !in.get(v.z())) return false;
  }
  for (Triangle& t : part.triangles) {
    if (!in.get(t)) return false;
  }
  return true;
}

// The parts stored in bytes, or nothing if they are not a complete, intact, valid decomposition.
std::optional<std::vector<TriangleMesh>> deserialize(const std::string& bytes) {
  constexpr std::size_t kHashSize = sizeof(std::uint64_t);
  if (bytes.size() < sizeof kMagic + kHashSize ||
      std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) {
    return std::nullopt;
  }
  const std::size_t payload = bytes.size() - kHashSize;
  Fnv1a hash;
  hash.add(bytes.data(), payload);
  std::uint64_t stored_hash = 0;
  std::memcpy(&stored_hash, bytes.data() + payload, kHashSize);
  if (stored_hash != hash.value()) return std::nullopt;

  ByteReader in(bytes, payload);
  std::array<char, sizeof kMagic> magic{};
  std::uint64_t num_parts = 0;
  if (!in.get(magic) || !in.get(num_parts) || num_parts > in.left() / 16) return std::nullopt;
  std::vector<TriangleMesh> parts(num_parts);
  for (TriangleMesh& part : parts) {
    if (!read_part(in, part)) return std::nullopt;
    try {
      validate_mesh(part, "cached convex part");
    } catch (const Error&) {
      return std::nullopt;
    }
  }
  if (in.left() != 0) return std::nullopt;
  return parts;
}

std::optional<std::vector<TriangleMesh>> read_cache(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return std::nullopt;
  return deserialize(bytes);
}

void write_cache(const fs::path& path, const std::vector<TriangleMesh>& parts) {
  const fs::path folder = path.parent_path();
  std::error_code ec;
  if (!folder.empty() && !fs::create_directories(folder, ec) && ec) {
    throw Error("cannot create cache folder " + folder.string() + ": " + ec.message());
  }
  const std::string bytes = serialize(parts);
  write_atomically(path, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) throw Error("cannot write " + path.string() + ": write failed");
  });
}

}  // namespace

TriangleMesh convex_hull(const std::vector<Vec3>& points) {
  return Quickhull(points).mesh();
}

std::vector<TriangleMesh> convex_decomposition(const TriangleMesh& mesh,
                                               const DecompositionOptions& options) {
  check_options(options);
  check_closed(mesh);
  const double tolerance = options.concavity * std::abs(mass_properties(mesh).volume);
  const std::vector<Cell> cells = Splitter(mesh, options, tolerance).run();
  std::vector<TriangleMesh> parts;
  for (const Group& group : merge(cells, static_cast<std::size_t>(options.max_parts), tolerance)) {
    TriangleMesh hull = convex_hull(group.points);
    if (!hull.triangles.empty()) parts.push_back(std::move(hull));
  }
  return parts;
}

fs::path decomposition_cache_file(const TriangleMesh& mesh, const DecompositionOptions& options,
                                  const fs::path& cache_dir) {
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.convex",
                static_cast<unsigned long long>(cache_key(mesh, options)));
  return cache_dir / name;
}

std::vector<TriangleMesh> cached_convex_decomposition(const TriangleMesh& mesh,
                                                      const DecompositionOptions& options,
                                                      const fs::path& cache_dir) {
  const fs::path path = decomposition_cache_file(mesh, options, cache_dir);
  if (std::optional<std::vector<TriangleMesh>> parts = read_cache(path)) return std::move(*parts);
  std::vector<TriangleMesh> parts = convex_decomposition(mesh, options);
  write_cache(path, parts);
  return parts;
}

}  // namespace graspecmf::geometry
