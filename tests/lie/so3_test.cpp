#include "graspecmf/lie/so3.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <vector>

#include "graspecmf/core/random.hpp"
#include "graspecmf/lie/rotation_sets.hpp"

namespace graspecmf::lie {
namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 random_unit(Rng& rng) {
  Vec3 v(rng.normal(), rng.normal(), rng.normal());
  return v.normalized();
}

Vec3 random_vec(Rng& rng, double scale) {
  return Vec3(rng.uniform(-scale, scale), rng.uniform(-scale, scale), rng.uniform(-scale, scale));
}

double max_abs(const Mat3& M) {
  return M.cwiseAbs().maxCoeff();
}

// |log(exp(w)) − w| / |w| (absolute for w = 0).
double log_exp_error(const Vec3& w) {
  const Vec3 back = so3_log(so3_exp(w));
  const double n = w.norm();
  return (back - w).norm() / (n > 0.0 ? n : 1.0);
}

// exp by summing the matrix power series far past convergence (a reference for |w| ≤ 1).
Mat3 exp_series(const Vec3& w) {
  const Mat3 W = hat(w);
  Mat3 term = Mat3::Identity();
  Mat3 sum = Mat3::Identity();
  for (int k = 1; k < 40; ++k) {
    term = term * W / static_cast<double>(k);
    sum += term;
  }
  return sum;
}

// The textbook log without a near-π branch: θ/sin θ · vee(R).
Vec3 log_generic_only(const Mat3& R) {
  const Vec3 v = vee(R);
  const double theta = std::atan2(v.norm(), 0.5 * (R.trace() - 1.0));
  return theta / v.norm() * v;
}

// The near-π branch used everywhere: axis from (R + Rᵀ)/2 − cos θ I.
Vec3 log_symmetric_only(const Mat3& R) {
  const Vec3 v = vee(R);
  const double c = 0.5 * (R.trace() - 1.0);
  const double theta = std::atan2(v.norm(), c);
  const Mat3 B = 0.5 * (R + R.transpose()) - c * Mat3::Identity();
  Eigen::Index k = 0;
  B.diagonal().maxCoeff(&k);
  Vec3 a = B.col(k).normalized();
  if (a.dot(v) < 0.0) a = -a;
  return theta * a;
}

TEST(So3Hat, VeeInvertsHatAndHatIsCrossProduct) {
  Rng rng(1);
  for (int i = 0; i < 100; ++i) {
    const Vec3 w = random_vec(rng, 3.0);
    const Vec3 v = random_vec(rng, 3.0);
    const Mat3 W = hat(w);
    EXPECT_EQ(vee(W), w);
    EXPECT_EQ(W.transpose(), -W);
    EXPECT_LT((W * v - w.cross(v)).norm(), 1e-14);
  }
}

TEST(So3Hat, VeeReadsOnlyTheAntisymmetricPart) {
  Rng rng(2);
  const Vec3 w = random_vec(rng, 1.0);
  Mat3 S;
  for (int i = 0; i < 9; ++i) S(i / 3, i % 3) = rng.uniform(-1.0, 1.0);
  S = (S + S.transpose()).eval();  // eval: S appears on both sides
  EXPECT_LT((vee(hat(w) + S) - w).norm(), 1e-15);
}

TEST(So3Exp, ZeroAndIdentity) {
  EXPECT_EQ(so3_exp(Vec3::Zero()), Mat3::Identity());
  EXPECT_EQ(so3_log(Mat3::Identity()), Vec3::Zero());
  EXPECT_EQ(so3_angle(Mat3::Identity()), 0.0);
}

TEST(So3Exp, IsAProperRotation) {
  Rng rng(3);
  for (int i = 0; i < 1000; ++i) {
    // Angles from 0 up to 4π, including the Taylor branch for some.
    const double angle = (i % 10 == 0) ? rng.uniform(0.0, 1e-4) : rng.uniform(0.0, 4.0 * kPi);
    const Mat3 R = so3_exp(angle * random_unit(rng));
    EXPECT_LT(orthogonality_error(R), 1e-14) << angle;
    EXPECT_NEAR(R.determinant(), 1.0, 1e-14) << angle;
  }
}

TEST(So3Exp, RotatesAboutTheAxisByTheAngle) {
  // Exp(θ e_z) is the planar rotation by θ, and it fixes its axis.
  const double t = 0.7;
  Mat3 Rz;
  Rz << std::cos(t), -std::sin(t), 0, std::sin(t), std::cos(t), 0, 0, 0, 1;
  EXPECT_LT(max_abs(so3_exp(Vec3(0, 0, t)) - Rz), 1e-15);
  Rng rng(4);
  const Vec3 w = 2.0 * random_unit(rng);
  EXPECT_LT((so3_exp(w) * w - w).norm(), 1e-15);
}

TEST(So3Exp, MatchesThePowerSeriesAcrossTheTaylorSwitch) {
  Rng rng(5);
  for (const double angle : {1e-12, 1e-8, 1e-5, 0.99e-4, 1e-4, 1.01e-4, 1e-3, 0.1, 0.5, 1.0}) {
    for (int i = 0; i < 20; ++i) {
      const Vec3 w = angle * random_unit(rng);
      // Off-diagonal entries are O(θ); compare them relative to θ as well.
      const Mat3 D = so3_exp(w) - exp_series(w);
      EXPECT_LT(max_abs(D), 4e-16) << angle;
      Mat3 off = D;
      off.diagonal().setZero();
      EXPECT_LT(max_abs(off) / angle, 1e-14) << angle;
    }
  }
}

TEST(So3Exp, TinyAngleIsNotTheIdentity) {
  Rng rng(6);
  for (const double angle : {1e-9, 1e-12, 1e-15}) {
    const Vec3 w = angle * random_unit(rng);
    const Mat3 R = so3_exp(w);
    EXPECT_NE(R, Mat3::Identity());
    // exp(w) − I = [w]× + O(θ²): the first-order part must be exact to rounding.
    EXPECT_LT((vee(R - Mat3::Identity()) - w).norm() / angle, 1e-14) << angle;
  }
}

TEST(So3LogExp, RoundTripNearIdentity) {
  Rng rng(7);
  for (const double angle : {1e-9, 1e-12, 1e-6, 1e-4, 1.0001e-4, 0.9999e-4}) {
    for (int i = 0; i < 20; ++i) {
      const Vec3 w = angle * random_unit(rng);
      EXPECT_LT(log_exp_error(w), 1e-12) << angle;
      EXPECT_NEAR(so3_angle(so3_exp(w)), angle, 1e-14 * angle);
      const Mat3 R = so3_exp(w);
      EXPECT_LT(max_abs(so3_exp(so3_log(R)) - R), 1e-15);
    }
  }
}

TEST(So3LogExp, RoundTripOnRandomRotations) {
  Rng rng(8);
  double worst = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const Vec3 w = rng.uniform(0.0, kPi) * random_unit(rng);
    worst = std::max(worst, log_exp_error(w));
    EXPECT_LE(so3_log(so3_exp(w)).norm(), kPi);
  }
  EXPECT_LT(worst, 1e-12);
  for (const Mat3& R : random_rotations(1000, 9)) {
    const Vec3 w = so3_log(R);
    EXPECT_LE(w.norm(), kPi);
    EXPECT_LT(max_abs(so3_exp(w) - R), 1e-14);
  }
}

TEST(So3LogExp, RoundTripNearPi) {
  Rng rng(10);
  for (const double gap : {1e-3, 1e-6, 1e-9, 1e-12}) {
    for (int i = 0; i < 100; ++i) {
      const Vec3 w = (kPi - gap) * random_unit(rng);
      EXPECT_LT(log_exp_error(w), 1e-12) << gap;
      const Mat3 R = so3_exp(w);
      EXPECT_LT(max_abs(so3_exp(so3_log(R)) - R), 1e-14) << gap;
    }
  }
}

TEST(So3LogExp, AnglesBeyondPiWrapToTheShortWay) {
  Rng rng(11);
  for (int i = 0; i < 200; ++i) {
    const double angle = rng.uniform(kPi + 1e-6, 2.0 * kPi - 1e-3);
    const Vec3 a = random_unit(rng);
    const Vec3 expected = -(2.0 * kPi - angle) * a;
    EXPECT_LT((so3_log(so3_exp(angle * a)) - expected).norm(), 1e-12) << angle;
  }
}

TEST(So3LogExp, ExactHalfTurns) {
  std::vector<Mat3> half_turns = {Vec3(1, -1, -1).asDiagonal(), Vec3(-1, 1, -1).asDiagonal(),
                                  Vec3(-1, -1, 1).asDiagonal()};
  Rng rng(12);
  for (int i = 0; i < 50; ++i) {
    const Vec3 a = random_unit(rng);
    half_turns.push_back(2.0 * a * a.transpose() - Mat3::Identity());  // exactly symmetric
    half_turns.push_back(so3_exp(kPi * a));
  }
  const Vec3 diag_axis = so3_log(half_turns[0]);
  EXPECT_NEAR(std::abs(diag_axis.x()), kPi, 1e-15);
  EXPECT_EQ(diag_axis.y(), 0.0);
  EXPECT_EQ(diag_axis.z(), 0.0);
  for (const Mat3& R : half_turns) {
    const Vec3 w = so3_log(R);
    EXPECT_NEAR(w.norm(), kPi, 1e-12);
    EXPECT_NEAR(so3_angle(R), kPi, 1e-12);
    EXPECT_LT(max_abs(so3_exp(w) - R), 1e-9);
    EXPECT_LT(max_abs(so3_exp(w) - R), 1e-14);  // in fact to rounding
  }
}

// Justifies kNearPiCos = −0.9 in so3.cpp. The generic formula θ/sin θ · vee(R) loses accuracy as
// eps/sin θ and the symmetric-part formula as eps/(1 − cos θ). At cos θ = −0.9 (θ ≈ 2.69 rad) both
// are accurate to a few ulps, so switching there loses nothing; near π only the second one is.
TEST(So3LogNearPiThreshold, BothBranchesAreAccurateAtTheSwitch) {
  Rng rng(13);
  const double switch_angle = std::acos(-0.9);
  for (const double angle : {switch_angle - 0.05, switch_angle, switch_angle + 0.05}) {
    for (int i = 0; i < 200; ++i) {
      const Vec3 w = angle * random_unit(rng);
      const Mat3 R = so3_exp(w);
      EXPECT_LT((log_generic_only(R) - w).norm() / angle, 1e-15) << angle;
      EXPECT_LT((log_symmetric_only(R) - w).norm() / angle, 1e-15) << angle;
      EXPECT_LT(log_exp_error(w), 1e-15) << angle;
    }
  }
}

TEST(So3LogNearPiThreshold, GenericFormulaFailsNearPiSymmetricFailsNearZero) {
  Rng rng(14);
  double generic_near_pi = 0.0;
  double ours_near_pi = 0.0;
  double symmetric_near_zero = 0.0;
  for (int i = 0; i < 50; ++i) {
    const Vec3 a = random_unit(rng);
    const Vec3 w_pi = (kPi - 1e-9) * a;
    const Mat3 R_pi = so3_exp(w_pi);
    generic_near_pi = std::max(generic_near_pi, (log_generic_only(R_pi) - w_pi).norm() / kPi);
    ours_near_pi = std::max(ours_near_pi, log_exp_error(w_pi));
    const Vec3 w_0 = 1e-6 * a;
    symmetric_near_zero =
        std::max(symmetric_near_zero, (log_symmetric_only(so3_exp(w_0)) - w_0).norm() / 1e-6);
  }
  EXPECT_GT(generic_near_pi, 1e-9);  // ~eps / sin θ ≈ 1e-7
  EXPECT_LT(ours_near_pi, 1e-15);
  EXPECT_GT(symmetric_near_zero, 1e-6);  // ~eps / (1 − cos θ)
}

TEST(So3LogNearPiThreshold, SweepOverAllAngles) {
  // log ∘ exp stays at rounding level on a fine sweep from 1e-3 to π − 1e-9 rad (measured worst
  // 4.9e-16). Any switch in cos θ ∈ [−0.99, 0.5] gives the same; switching at cos θ = 0.99 (1.4e-14
  // near θ = 0.14) or at −0.9999 (6.8e-15 near π) would fail this bound.
  Rng rng(15);
  double worst = 0.0;
  for (int k = 0; k <= 20000; ++k) {
    const double angle = 1e-3 + (kPi - 1e-9 - 1e-3) * k / 20000.0;
    worst = std::max(worst, log_exp_error(angle * random_unit(rng)));
  }
  EXPECT_LT(worst, 1.5e-15);
}

TEST(So3Distance, MetricAxiomsAndBiInvariance) {
  const std::vector<Mat3> R = random_rotations(3000, 16);
  const std::vector<Mat3> G = random_rotations(1000, 17);
  for (int i = 0; i < 1000; ++i) {
    const Mat3& A = R[3 * i];
    const Mat3& B = R[3 * i + 1];
    const Mat3& C = R[3 * i + 2];
    const double ab = so3_distance(A, B);
    EXPECT_EQ(so3_distance(A, A), 0.0);
    EXPECT_GE(ab, 0.0);
    EXPECT_LE(ab, kPi);
    EXPECT_NEAR(ab, so3_distance(B, A), 1e-14);
    EXPECT_LE(ab, so3_distance(A, C) + so3_distance(C, B) + 1e-12);
    EXPECT_NEAR(so3_distance(G[i] * A, G[i] * B), ab, 1e-12);
    EXPECT_NEAR(so3_distance(A * G[i], B * G[i]), ab, 1e-12);
    EXPECT_NEAR(ab, so3_log(A.transpose() * B).norm(), 1e-14);
  }
}

TEST(So3Distance, SmallDistancesAreResolved) {
  const Mat3 A = random_rotations(1, 18)[0];
  const Vec3 w(3e-13, -4e-13, 0.0);
  EXPECT_NEAR(so3_distance(A, A * so3_exp(w)), 5e-13, 1e-15);
}

TEST(So3Interpolate, EndpointsAndConstantSpeed) {
  const std::vector<Mat3> R = random_rotations(400, 19);
  for (int i = 0; i < 200; ++i) {
    const Mat3& A = R[2 * i];
    const Mat3& B = R[2 * i + 1];
    const double d = so3_distance(A, B);
    EXPECT_EQ(so3_interpolate(A, B, 0.0), A);
    EXPECT_LT(max_abs(so3_interpolate(A, B, 1.0) - B), 1e-14);
    const Mat3 M = so3_interpolate(A, B, 0.5);
    EXPECT_NEAR(so3_distance(A, M), so3_distance(M, B), 1e-12);
    for (const double t : {0.1, 0.25, 0.5, 0.8, 0.99}) {
      const Mat3 Rt = so3_interpolate(A, B, t);
      EXPECT_LT(orthogonality_error(Rt), 1e-14);
      EXPECT_NEAR(so3_distance(A, Rt), t * d, 1e-12) << t;
      EXPECT_NEAR(so3_distance(Rt, B), (1.0 - t) * d, 1e-12) << t;
    }
  }
}

TEST(So3Checks, OrthogonalityErrorAndIsRotation) {
  const Mat3 R = random_rotations(1, 20)[0];
  EXPECT_LT(orthogonality_error(R), 1e-15);
  EXPECT_TRUE(is_rotation(R));
  EXPECT_NEAR(orthogonality_error(1.01 * R), 0.0201, 1e-12);
  EXPECT_FALSE(is_rotation(1.01 * R));
  EXPECT_TRUE(is_rotation(1.01 * R, 0.03));
  const Mat3 reflection = R * Vec3(1, 1, -1).asDiagonal();
  EXPECT_LT(orthogonality_error(reflection), 1e-15);  // orthonormal, but det = −1
  EXPECT_FALSE(is_rotation(reflection));
  Mat3 bad = R;
  bad(1, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(is_rotation(bad));
  EXPECT_EQ(orthogonality_error(bad), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace graspecmf::lie
