#pragma once
// The rotation group SO(3) in double precision: hat/vee, exponential and logarithm maps that stay
// accurate near the identity (Taylor branches) and near a half turn (θ → π), distances and
// geodesics.

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products, quaternions

namespace graspecmf::lie {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// The skew-symmetric matrix [w]× with [w]× v = w × v.
Mat3 hat(const Vec3& w);
// The vector of a skew-symmetric matrix (reads the antisymmetric part of W); vee(hat(w)) = w.
Vec3 vee(const Mat3& W);

// Exp(w) = rotation by angle |w| about w / |w| (Rodrigues); exact to rounding for every w.
Mat3 so3_exp(const Vec3& w);
// Log(R) with angle in [0, π]; accurate near 0 and near π (at exactly π the sign is arbitrary).
// R must be a rotation to within ~1e-9.
Vec3 so3_log(const Mat3& R);
// The rotation angle of R in [0, π].
double so3_angle(const Mat3& R);
// Geodesic distance: the angle of Aᵀ B, in [0, π].
double so3_distance(const Mat3& A, const Mat3& B);
// The geodesic from R0 (t = 0) to R1 (t = 1): R0 Exp(t Log(R0ᵀ R1)).
Mat3 so3_interpolate(const Mat3& R0, const Mat3& R1, double t);

// Largest absolute entry of RᵀR − I (+∞ if an entry of R is not finite); det(R) is not part of it.
double orthogonality_error(const Mat3& R);
// True when R is orthonormal to within tol and det(R) > 0.
bool is_rotation(const Mat3& R, double tol = 1e-6);

}  // namespace graspecmf::lie
