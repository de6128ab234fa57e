#pragma once
// Oriented boxes as simple collision shapes: a triangle mesh of the box, and exact overlap tests
// against a triangle (separating-axis theorem) and against a closed triangle mesh.

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

struct OrientedBox {
  lie::Pose pose;  // box frame → world: the box is centred at pose.p with axes pose.R
  Vec3 half_extents = Vec3::Zero();
};

// The box as a closed, outward-oriented mesh of 8 vertices and 12 triangles.
TriangleMesh box_mesh(const OrientedBox& box);
// The box mapped by a rigid transform.
OrientedBox transformed(const OrientedBox& box, const lie::Pose& pose);
// True if the solid box and the triangle abc intersect (touching counts).
bool box_overlaps_triangle(const OrientedBox& box, const Vec3& a, const Vec3& b, const Vec3& c);
// True if the box intersects any triangle of the mesh or lies inside the closed mesh.
bool box_overlaps_mesh(const OrientedBox& box, const TriangleMesh& mesh);

}  // namespace graspecmf::geometry
