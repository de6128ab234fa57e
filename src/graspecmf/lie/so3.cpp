#include "graspecmf/lie/so3.hpp"

#include <Eigen/LU>
#include <cmath>
#include <limits>

namespace graspecmf::lie {

namespace {

// Below this angle the Taylor series are used; the first omitted terms are O(θ⁶) ≈ 1e-24.
constexpr double kSmallAngle = 1e-4;
// so3_log switches to the symmetric-part axis recovery when cos θ < this (θ > ~2.69 rad). The
// generic θ/sin θ · vee(R) loses ~eps/sin θ, the symmetric part ~eps/(1 − cos θ); at the switch
// sin θ ≈ 0.44 and 1 − cos θ = 1.9, so both are accurate to rounding (So3LogNearPiThreshold tests).
constexpr double kNearPiCos = -0.9;

// sin θ and cos θ of R: |antisymmetric part| and (tr R − 1)/2, and the angle from both.
struct AngleParts {
  Vec3 v;  // sin θ · axis
  double sin_theta;
  double cos_theta;
  double theta;
};

AngleParts angle_parts(const Mat3& R) {
  AngleParts a;
  a.v = vee(R);
  a.sin_theta = a.v.norm();
  a.cos_theta = 0.5 * (R.trace() - 1.0);
  a.theta = std::atan2(a.sin_theta, a.cos_theta);
  return a;
}

}  // namespace

Mat3 hat(const Vec3& w) {
  Mat3 W;
  W << 0.0, -w.z(), w.y(),  //
      w.z(), 0.0, -w.x(),   //
      -w.y(), w.x(), 0.0;
  return W;
}

Vec3 vee(const Mat3& W) {
  return 0.5 * Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
}

Mat3 so3_exp(const Vec3& w) {
  const double theta2 = w.squaredNorm();
  const double theta = std::sqrt(theta2);
  double a;  // sin θ / θ
  double b;  // (1 − cos θ) / θ²
  if (theta < kSmallAngle) {
    a = 1.0 - theta2 / 6.0 + theta2 * theta2 / 120.0;
    b = 0.5 - theta2 / 24.0 + theta2 * theta2 / 720.0;
  } else {
    a = std::sin(theta) / theta;
    // (1 − cos θ)/θ² = ½ (sin(θ/2) / (θ/2))², free of cancellation.
    const double half_sinc = std::sin(0.5 * theta) / (0.5 * theta);
    b = 0.5 * half_sinc * half_sinc;
  }
  const Mat3 W = hat(w);
  return Mat3::Identity() + a * W + b * (W * W);
}

Vec3 so3_log(const Mat3& R) {
  const AngleParts p = angle_parts(R);
  if (p.cos_theta >= kNearPiCos) {
    double scale;  // θ / sin θ
    if (p.theta < kSmallAngle) {
      const double t2 = p.theta * p.theta;
      scale = 1.0 + t2 / 6.0 + 7.0 * t2 * t2 / 360.0;
    } else {
      scale = p.theta / p.sin_theta;
    }
    return scale * p.v;
  }
  // Near π: (R + Rᵀ)/2 − cos θ I = (1 − cos θ) a aᵀ; its column with the largest diagonal is the
  // best-conditioned multiple of the axis a.
  const Mat3 B = 0.5 * (R + R.transpose()) - p.cos_theta * Mat3::Identity();
  Eigen::Index k = 0;
  B.diagonal().maxCoeff(&k);
  Vec3 axis = B.col(k).normalized();
  if (axis.dot(p.v) < 0.0) axis = -axis;
  return p.theta * axis;
}

double so3_angle(const Mat3& R) {
  return angle_parts(R).theta;
}

double so3_distance(const Mat3& A, const Mat3& B) {
  return so3_angle(A.transpose() * B);
}

Mat3 so3_interpolate(const Mat3& R0, const Mat3& R1, double t) {
  return R0 * so3_exp(t * so3_log(R0.transpose() * R1));
}

double orthogonality_error(const Mat3& R) {
  if (!R.allFinite()) return std::numeric_limits<double>::infinity();
  return (R.transpose() * R - Mat3::Identity()).cwiseAbs().maxCoeff();
}

bool is_rotation(const Mat3& R, double tol) {
  return orthogonality_error(R) <= tol && R.determinant() > 0.0;
}

}  // namespace graspecmf::lie
