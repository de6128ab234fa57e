#include "graspecmf/lie/se3.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

namespace graspecmf::lie {

Pose Pose::from_matrix(const Mat4& T) {
  Pose x;
  x.R = T.topLeftCorner<3, 3>();
  x.p = T.topRightCorner<3, 1>();
  return x;
}

Mat4 Pose::matrix() const {
  Mat4 T = Mat4::Identity();
  T.topLeftCorner<3, 3>() = R;
  T.topRightCorner<3, 1>() = p;
  return T;
}

Pose compose(const Pose& a, const Pose& b) {
  Pose c;
  c.R = a.R * b.R;
  c.p = a.R * b.p + a.p;
  return c;
}

Pose inverse(const Pose& x) {
  Pose y;
  y.R = x.R.transpose();
  y.p = -(y.R * x.p);
  return y;
}

Vec3 apply(const Pose& pose, const Vec3& x) {
  return pose.R * x + pose.p;
}

double pose_distance(const Pose& a, const Pose& b) {
  return std::hypot(so3_distance(a.R, b.R), (a.p - b.p).norm());
}

Pose quantized(const Pose& pose, double grid) {
  Eigen::Quaterniond q(pose.R);
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  q.coeffs() = rounded(Eigen::Vector4d(q.coeffs()), grid);
  Pose out;
  out.R = q.normalized().toRotationMatrix();
  out.p = rounded(pose.p, grid);
  return out;
}

Pose pose_interpolate(const Pose& a, const Pose& b, double t) {
  Pose x;
  x.R = so3_interpolate(a.R, b.R, t);
  x.p = (1.0 - t) * a.p + t * b.p;
  return x;
}

double rigidity_error(const Mat4& T) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (!T.allFinite()) return kInf;
  const Mat3 R = T.topLeftCorner<3, 3>();
  if (!(R.determinant() > 0.0)) return kInf;
  const double row_error = (T.row(3) - Eigen::RowVector4d(0.0, 0.0, 0.0, 1.0)).norm();
  return std::max(orthogonality_error(R), row_error);
}

}  // namespace graspecmf::lie
