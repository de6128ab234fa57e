#pragma once
// Surface pieces as lists of convex polygons, and their clipping by axis-aligned planes (used to
// restrict a mesh surface to the boxes of a lattice).

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

// Convex polygons stored back to back. close_polygon(first) keeps the points appended since index
// `first` as one polygon if there are at least 3 of them, else drops them; append adds a polygon.
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

// The mesh's triangles as polygons, in triangle order (degenerate ones included).
Polygons mesh_polygons(const TriangleMesh& mesh);
// True if every point of the polygon has coordinate c along axis.
bool lies_in_plane(const Vec3* polygon, std::size_t n, int axis, double c);
// The polygons clipped to x[axis] ≤ c (first) and x[axis] ≥ c (second); a polygon lying in the
// plane goes whole to the side its solid is on (outward normal towards +axis: first).
std::pair<Polygons, Polygons> split_polygons(const Polygons& polygons, int axis, double c);

}  // namespace graspecmf::geometry
