#include "graspecmf/geometry/convex_decomposition.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/convex_hull.hpp"
#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"
#include "graspecmf/geometry/polygon_clipping.hpp"
#include "graspecmf/geometry/voxel_grid.hpp"

namespace graspecmf::geometry {

// The decomposition works on boxes (cells) of a regular lattice around the mesh. For each cell it
// knows the convex hull of the solid inside it exactly (built from the mesh surface clipped to the
// cell plus the cell corners inside the solid) and the solid's volume exactly (a flux integral).
// Phase 1 splits the cell whose hull exceeds its solid by the most, at the lattice plane that
// reduces that excess the most (or, when no plane helps much, across its longest side), until every
// excess is within the tolerance. Phase 2 merges touching cells, cheapest added hull volume first,
// down to the part budget. Every part is the hull of the solid in its cells, so the parts cover the
// solid exactly; hulls of merged cells may overlap a little.

namespace {

constexpr int kMinResolution = 4;
constexpr int kMaxResolution = 256;

using Index3 = std::array<int, 3>;

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
    ConvexHull hull = convex_hull_with_volume(cell.points);
    cell.hull_vertices = std::move(hull.mesh.vertices);
    cell.hull_volume = hull.volume;
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
  ConvexHull hull = convex_hull_with_volume(points);
  return {std::move(hull.mesh.vertices), hull.volume, solid_volume, true};
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

}  // namespace

std::vector<TriangleMesh> convex_decomposition(const TriangleMesh& mesh,
                                               const DecompositionOptions& options) {
  check_options(options);
  require_watertight(mesh, "convex_decomposition");
  const double tolerance = options.concavity * std::abs(mass_properties(mesh).volume);
  const std::vector<Cell> cells = Splitter(mesh, options, tolerance).run();
  std::vector<TriangleMesh> parts;
  for (const Group& group : merge(cells, static_cast<std::size_t>(options.max_parts), tolerance)) {
    TriangleMesh hull = convex_hull(group.points);
    if (!hull.triangles.empty()) parts.push_back(std::move(hull));
  }
  return parts;
}

}  // namespace graspecmf::geometry
