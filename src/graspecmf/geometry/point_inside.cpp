#include "graspecmf/geometry/point_inside.hpp"

#include <cmath>

namespace graspecmf::geometry {

double winding_number(const TriangleMesh& mesh, const Vec3& q) {
  double total = 0.0;
  for (const Triangle& tri : mesh.triangles) {
    const Vec3 a = mesh.vertices[tri[0]] - q;
    const Vec3 b = mesh.vertices[tri[1]] - q;
    const Vec3 c = mesh.vertices[tri[2]] - q;
    const double la = a.norm();
    const double lb = b.norm();
    const double lc = c.norm();
    // Van Oosterom–Strackee: tan(Ω/2) = a·(b×c) / (|a||b||c| + (a·b)|c| + (b·c)|a| + (c·a)|b|).
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2.0 * std::atan2(numerator, denominator);
  }
  constexpr double kFourPi = 4.0 * 3.14159265358979323846;
  return total / kFourPi;
}

bool is_inside(const TriangleMesh& mesh, const Vec3& q) {
  // A point outside the bounding box is outside; the O(V) box test is far cheaper than the
  // O(F) solid-angle sum.
  const BoundingBox box = bounding_box(mesh);
  if ((q.array() < box.min.array()).any() || (q.array() > box.max.array()).any()) return false;
  return winding_number(mesh, q) > 0.5;
}

}  // namespace graspecmf::geometry
