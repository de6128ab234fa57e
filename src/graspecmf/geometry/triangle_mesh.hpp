#pragma once
// TriangleMesh, an indexed triangle list in double precision, and the basic per-mesh queries:
// validation, bounding box, per-triangle area and normal, scaling and rigid transformation.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "graspecmf/lie/se3.hpp"

namespace graspecmf::geometry {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<std::uint32_t, 3>;

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;  // counter-clockwise seen from outside = outward normal
};

struct BoundingBox {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Zero();

  Vec3 extent() const { return max - min; }
  Vec3 center() const { return 0.5 * (min + max); }
};

// Throws Error naming `what` if the mesh has no triangles, a non-finite coordinate, a vertex index
// out of range, or a triangle that repeats a vertex index.
void validate_mesh(const TriangleMesh& mesh, const std::string& what);
// Axis-aligned bounds of the vertices that triangles use; throws Error on a mesh without triangles.
BoundingBox bounding_box(const TriangleMesh& mesh);
// Area of triangle t.
double triangle_area(const TriangleMesh& mesh, std::size_t t);
// Unit normal of triangle t (right-hand rule on its vertex order); zero for a degenerate triangle.
Vec3 triangle_normal(const TriangleMesh& mesh, std::size_t t);
// Total surface area.
double surface_area(const TriangleMesh& mesh);
// Every vertex multiplied by factor (ACRONYM: metric mesh = raw mesh × scale).
TriangleMesh scaled(const TriangleMesh& mesh, double factor);
// Every vertex mapped by pose (R v + p).
TriangleMesh transformed(const TriangleMesh& mesh, const lie::Pose& pose);
// Every coordinate rounded to a multiple of `grid` (a power of two keeps it exact): meshes that
// differ by round-off become bit-identical, except where a coordinate straddles a step.
TriangleMesh quantized(const TriangleMesh& mesh, double grid);

}  // namespace graspecmf::geometry
