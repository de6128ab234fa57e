#pragma once
// Inside/outside tests for closed meshes by the generalised winding number (robust to the ray
// degeneracies of parity counting).

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

// Σ solid angles / 4π of the triangles seen from q: 1 inside, 0 outside a closed outward mesh
// (−1 inside an inward one). On the surface itself the value is not defined.
double winding_number(const TriangleMesh& mesh, const Vec3& q);
// winding_number(mesh, q) > 0.5 (false at once outside the bounding box).
bool is_inside(const TriangleMesh& mesh, const Vec3& q);

}  // namespace graspecmf::geometry
