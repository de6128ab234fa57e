#include "graspecmf/geometry/polygon_clipping.hpp"

#include <algorithm>

namespace graspecmf::geometry {

namespace {

// Where edge a–b crosses the plane x[axis] = c (they lie strictly on either side), computed from
// the lower end so that both polygons sharing the edge get the same point.
Vec3 crossing(const Vec3& a, const Vec3& b, int axis, double c) {
  const Vec3& lo = a[axis] < b[axis] ? a : b;
  const Vec3& hi = a[axis] < b[axis] ? b : a;
  Vec3 x = lo + ((c - lo[axis]) / (hi[axis] - lo[axis])) * (hi - lo);
  x[axis] = c;
  return x;
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

}  // namespace

Polygons mesh_polygons(const TriangleMesh& mesh) {
  Polygons out;
  for (const Triangle& tri : mesh.triangles) {
    const Vec3 corners[3] = {mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]};
    out.append(corners, 3);
  }
  return out;
}

// True if every point of the polygon has coordinate c along axis.
bool lies_in_plane(const Vec3* polygon, std::size_t n, int axis, double c) {
  return std::all_of(polygon, polygon + n, [&](const Vec3& p) { return p[axis] == c; });
}

std::pair<Polygons, Polygons> split_polygons(const Polygons& polygons, int axis, double c) {
  std::pair<Polygons, Polygons> out;
  for_each_polygon(polygons, [&](const Vec3* polygon, std::size_t n) {
    split_polygon(polygon, n, axis, c, out.first, out.second);
  });
  return out;
}

}  // namespace graspecmf::geometry
