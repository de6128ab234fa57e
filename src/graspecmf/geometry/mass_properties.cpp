#include "graspecmf/geometry/mass_properties.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "graspecmf/core/error.hpp"

namespace graspecmf::geometry {

MassProperties mass_properties(const TriangleMesh& mesh, double density) {
  // Tetrahedra are taken from the bounding-box centre rather than the origin, so that the terms
  // stay of the mesh's own size when it lies far from the origin (less cancellation).
  const BoundingBox box = bounding_box(mesh);
  const Vec3 origin = box.center();

  double volume = 0.0;
  Vec3 first_moment = Vec3::Zero();   // ∫ x dV about origin
  Mat3 second_moment = Mat3::Zero();  // ∫ x xᵀ dV about origin
  for (const Triangle& tri : mesh.triangles) {
    const Vec3 a = mesh.vertices[tri[0]] - origin;
    const Vec3 b = mesh.vertices[tri[1]] - origin;
    const Vec3 c = mesh.vertices[tri[2]] - origin;
    // Signed volume of the tetrahedron (0, a, b, c).
    const double v = a.dot(b.cross(c)) / 6.0;
    const Vec3 sum = a + b + c;
    volume += v;
    first_moment += v * sum / 4.0;
    // ∫ x xᵀ over that tetrahedron: V/20 (a aᵀ + b bᵀ + c cᵀ + s sᵀ), s = a + b + c.
    second_moment += (v / 20.0) * (a * a.transpose() + b * b.transpose() + c * c.transpose() +
                                   sum * sum.transpose());
  }

  const double scale = box.extent().maxCoeff();
  if (!std::isfinite(volume) || std::abs(volume) <= 1e-12 * scale * scale * scale) {
    throw Error("mass_properties: the mesh encloses no volume (open or flat mesh?)");
  }
  const Vec3 com = first_moment / volume;
  // Parallel-axis shift of the second moment to the centre of mass.
  const Mat3 central = second_moment - volume * com * com.transpose();

  MassProperties out;
  out.volume = volume;
  out.mass = density * volume;
  out.center_of_mass = origin + com;
  out.inertia = density * (central.trace() * Mat3::Identity() - central);
  return out;
}

double third_moment(const std::vector<Vec3>& points, const Vec3& centre, const Vec3& axis) {
  double sum = 0.0;
  for (const Vec3& p : points) {
    const double along = axis.dot(p - centre);
    sum += along * along * along;
  }
  return sum;
}

lie::Pose principal_frame(const TriangleMesh& mesh) {
  const MassProperties mp = mass_properties(mesh);
  // Inward-facing meshes have negated inertia; the axes are the same.
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(mp.volume < 0 ? Mat3(-mp.inertia) : mp.inertia);
  Mat3 axes = solver.eigenvectors();  // columns, ascending eigenvalues
  for (int k = 0; k < 2; ++k) {
    if (third_moment(mesh.vertices, mp.center_of_mass, axes.col(k)) < 0) axes.col(k) *= -1.0;
  }
  axes.col(2) = axes.col(0).cross(axes.col(1));
  lie::Pose frame;
  frame.R = axes;
  frame.p = mp.center_of_mass;
  return frame;
}

}  // namespace graspecmf::geometry
