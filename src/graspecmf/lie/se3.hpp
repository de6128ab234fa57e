#pragma once
// Rigid transforms SE(3) as (R, p): composition, inverse, action on points, conversion to and from
// 4×4 matrices, the product distance sqrt(θ² + |Δp|²) of docs/method.md ("Evaluation: the EMD"),
// and the flow-matching path.

#include <Eigen/Core>

#include "graspecmf/lie/so3.hpp"

namespace graspecmf::lie {

using Mat4 = Eigen::Matrix4d;

struct Pose {
  Mat3 R = Mat3::Identity();
  Vec3 p = Vec3::Zero();

  // Reads the rotation block and translation column; the last row is not checked.
  static Pose from_matrix(const Mat4& T);
  // The homogeneous 4×4 matrix [R p; 0 0 0 1].
  Mat4 matrix() const;
};

// a ∘ b: apply b first, then a.
Pose compose(const Pose& a, const Pose& b);
// The inverse transform (Rᵀ, −Rᵀ p).
Pose inverse(const Pose& x);
// R x + p.
Vec3 apply(const Pose& pose, const Vec3& x);
// sqrt(θ² + |p_a − p_b|²) with θ the angle of R_aᵀ R_b (radians and metres, 1 rad ≙ 1 m).
double pose_distance(const Pose& a, const Pose& b);
// Rotation along the SO(3) geodesic, position along the straight line: the flow-matching path.
Pose pose_interpolate(const Pose& a, const Pose& b, double t);
// Every entry of a vector or matrix rounded to a multiple of grid.
template <typename Matrix>
Matrix rounded(const Matrix& m, double grid) {
  return (m / grid).array().round() * grid;
}
// The pose with its position and its rotation's unit quaternion (w ≥ 0) rounded to multiples of
// `grid` (a power of two keeps it exact), the quaternion renormalised: poses that differ by
// round-off become bit-identical, except in the rare case that a coordinate straddles a step.
Pose quantized(const Pose& pose, double grid);

// Largest deviation of T from a proper rigid transform: max of |RᵀR − I| entries and of the last
// row's distance from (0, 0, 0, 1); +∞ if det(R) ≤ 0 or any entry is not finite.
double rigidity_error(const Mat4& T);

}  // namespace graspecmf::lie
