#include "graspecmf/geometry/oriented_box.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "graspecmf/geometry/point_inside.hpp"

namespace graspecmf::geometry {

TriangleMesh box_mesh(const OrientedBox& box) {
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    mesh.vertices.push_back(box.pose.R * corner.cwiseProduct(box.half_extents) + box.pose.p);
  }
  // Two triangles per face, counter-clockwise seen from outside (vertex bit k = +axis k).
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}

OrientedBox transformed(const OrientedBox& box, const lie::Pose& pose) {
  return {lie::compose(pose, box.pose), box.half_extents};
}

bool box_overlaps_triangle(const OrientedBox& box, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Work in the box frame, where the box is the axis-aligned [-h, h].
  const Vec3& h = box.half_extents;
  const std::array<Vec3, 3> v = {box.pose.R.transpose() * (a - box.pose.p),
                                 box.pose.R.transpose() * (b - box.pose.p),
                                 box.pose.R.transpose() * (c - box.pose.p)};
  // Separated along axis if the triangle's projection interval misses the box's [-r, r].
  const auto separated = [&](const Vec3& axis) {
    const double p0 = axis.dot(v[0]), p1 = axis.dot(v[1]), p2 = axis.dot(v[2]);
    const double r = h.dot(axis.cwiseAbs());
    return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
  };
  for (int k = 0; k < 3; ++k) {
    if (separated(Vec3::Unit(k))) return false;
  }
  const std::array<Vec3, 3> edges = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
  if (separated(edges[0].cross(edges[1]))) return false;
  for (int k = 0; k < 3; ++k) {
    for (const Vec3& edge : edges) {
      if (separated(Vec3::Unit(k).cross(edge))) return false;
    }
  }
  return true;
}

bool box_overlaps_mesh(const OrientedBox& box, const TriangleMesh& mesh) {
  // Cull triangles by the box's world-frame bounding sphere before the exact test.
  const double radius = box.half_extents.norm();
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3& b = mesh.vertices[t[1]];
    const Vec3& c = mesh.vertices[t[2]];
    const Vec3 lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    const Vec3 nearest = box.pose.p.cwiseMax(lo).cwiseMin(hi);
    if ((nearest - box.pose.p).squaredNorm() > radius * radius) continue;
    if (box_overlaps_triangle(box, a, b, c)) return true;
  }
  return is_inside(mesh, box.pose.p);
}

}  // namespace graspecmf::geometry
