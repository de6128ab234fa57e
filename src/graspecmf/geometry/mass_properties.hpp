#pragma once
// Volume, centre of mass and inertia tensor of a closed triangle mesh of uniform density, by the
// divergence theorem (a signed tetrahedron per triangle, from the bounding-box centre so that a
// mesh far from the origin keeps its accuracy).

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

using Mat3 = Eigen::Matrix3d;

struct MassProperties {
  double volume = 0.0;  // signed: negative when the triangles face inwards
  double mass = 0.0;    // density × volume
  Vec3 center_of_mass = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();  // about the centre of mass, standard sign (positive-definite)
};

// Mass properties of a closed, consistently oriented mesh; results for an open mesh are
// meaningless. An inward-facing mesh gives the same centre of mass and negated volume, mass and
// inertia. Throws Error if the mesh has no triangles or its volume is zero (|V| ≤ 1e-12 × extent³).
MassProperties mass_properties(const TriangleMesh& mesh, double density = 1.0);

// Σ ((p − centre) · axis)³ over the points: its sign tells the two directions of a symmetry axis
// apart in a way that moves with the points.
double third_moment(const std::vector<Vec3>& points, const Vec3& centre, const Vec3& axis);

// A frame fixed to a closed mesh's solid, so that it moves rigidly with the mesh: origin at the
// centre of mass, axes the principal axes of inertia (ascending moments), each axis signed so that
// the vertices' third moment along it is positive (the last axis completes a right-handed frame).
// Throws as mass_properties does.
lie::Pose principal_frame(const TriangleMesh& mesh);

}  // namespace graspecmf::geometry
