#include "graspecmf/lie/se3.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <vector>

#include "graspecmf/core/random.hpp"
#include "graspecmf/lie/rotation_sets.hpp"

namespace graspecmf::lie {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

Vec3 random_vec(Rng& rng, double scale) {
  return Vec3(rng.uniform(-scale, scale), rng.uniform(-scale, scale), rng.uniform(-scale, scale));
}

std::vector<Pose> random_poses(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Pose> out(n);
  for (Pose& x : out) {
    x.R = random_rotation(rng);
    x.p = random_vec(rng, 2.0);
  }
  return out;
}

double max_abs(const Mat4& M) {
  return M.cwiseAbs().maxCoeff();
}

TEST(Se3Pose, DefaultIsIdentity) {
  const Pose x;
  EXPECT_EQ(x.matrix(), Mat4::Identity());
}

TEST(Se3Pose, MatrixRoundTrip) {
  for (const Pose& x : random_poses(100, 1)) {
    const Mat4 T = x.matrix();
    EXPECT_EQ(T.row(3), Eigen::RowVector4d(0, 0, 0, 1));
    const Pose y = Pose::from_matrix(T);
    EXPECT_EQ(y.R, x.R);
    EXPECT_EQ(y.p, x.p);
    EXPECT_EQ(y.matrix(), T);
  }
}

TEST(Se3Pose, ComposeInverseApplyMatchMatrices) {
  const std::vector<Pose> P = random_poses(300, 2);
  Rng rng(3);
  for (int i = 0; i < 100; ++i) {
    const Pose& a = P[3 * i];
    const Pose& b = P[3 * i + 1];
    const Pose& c = P[3 * i + 2];
    const Vec3 x = random_vec(rng, 1.0);
    EXPECT_LT(max_abs(compose(a, b).matrix() - a.matrix() * b.matrix()), 1e-14);
    EXPECT_LT(max_abs(inverse(a).matrix() - a.matrix().inverse()), 1e-13);
    EXPECT_LT(max_abs(compose(a, inverse(a)).matrix() - Mat4::Identity()), 1e-14);
    EXPECT_LT(max_abs(compose(inverse(a), a).matrix() - Mat4::Identity()), 1e-14);
    EXPECT_LT(max_abs(compose(compose(a, b), c).matrix() - compose(a, compose(b, c)).matrix()),
              1e-14);
    const Eigen::Vector4d xh(x.x(), x.y(), x.z(), 1.0);
    EXPECT_LT((apply(a, x) - (a.matrix() * xh).head<3>()).norm(), 1e-14);
    EXPECT_LT((apply(compose(a, b), x) - apply(a, apply(b, x))).norm(), 1e-14);
    EXPECT_LT((apply(inverse(a), apply(a, x)) - x).norm(), 1e-14);
  }
}

TEST(Se3Distance, MetricAxiomsAndLeftInvariance) {
  const std::vector<Pose> P = random_poses(3000, 4);
  const std::vector<Pose> G = random_poses(1000, 5);
  for (int i = 0; i < 1000; ++i) {
    const Pose& a = P[3 * i];
    const Pose& b = P[3 * i + 1];
    const Pose& c = P[3 * i + 2];
    const double ab = pose_distance(a, b);
    EXPECT_EQ(pose_distance(a, a), 0.0);
    EXPECT_GT(ab, 0.0);
    EXPECT_NEAR(ab, pose_distance(b, a), 1e-14);
    EXPECT_LE(ab, pose_distance(a, c) + pose_distance(c, b) + 1e-12);
    // g·x = (Q R, Q p + t) leaves both θ and |Δp| unchanged.
    EXPECT_NEAR(pose_distance(compose(G[i], a), compose(G[i], b)), ab, 1e-12);
  }
}

TEST(Se3Distance, CombinesAngleAndTranslation) {
  Pose a;
  Pose b;
  b.R = so3_exp(Vec3(0.0, 0.3, 0.0));
  EXPECT_NEAR(pose_distance(a, b), 0.3, 1e-15);
  b.R.setIdentity();
  b.p = Vec3(0.0, 0.0, 0.4);
  EXPECT_NEAR(pose_distance(a, b), 0.4, 1e-15);
  b.R = so3_exp(Vec3(0.3, 0.0, 0.0));
  EXPECT_NEAR(pose_distance(a, b), 0.5, 1e-15);
  b.R = Vec3(1, -1, -1).asDiagonal();  // exact half turn
  b.p = Vec3(1.0, 0.0, 0.0);
  EXPECT_NEAR(pose_distance(a, b), std::sqrt(kPi * kPi + 1.0), 1e-14);
}

TEST(Se3Interpolate, EndpointsAndConstantSpeed) {
  const std::vector<Pose> P = random_poses(200, 6);
  for (int i = 0; i < 100; ++i) {
    const Pose& a = P[2 * i];
    const Pose& b = P[2 * i + 1];
    const double d = pose_distance(a, b);
    const Pose x0 = pose_interpolate(a, b, 0.0);
    EXPECT_EQ(x0.R, a.R);
    EXPECT_EQ(x0.p, a.p);
    const Pose x1 = pose_interpolate(a, b, 1.0);
    EXPECT_LT(max_abs(x1.matrix() - b.matrix()), 1e-14);
    for (const double t : {0.2, 0.5, 0.75}) {
      const Pose xt = pose_interpolate(a, b, t);
      EXPECT_LT((xt.p - ((1.0 - t) * a.p + t * b.p)).norm(), 1e-15);
      EXPECT_NEAR(so3_distance(a.R, xt.R), t * so3_distance(a.R, b.R), 1e-12);
      EXPECT_NEAR(pose_distance(a, xt), t * d, 1e-12);
      EXPECT_NEAR(pose_distance(xt, b), (1.0 - t) * d, 1e-12);
    }
  }
}

TEST(Se3Rigidity, ZeroForRigidTransforms) {
  for (const Pose& x : random_poses(100, 7)) EXPECT_LT(rigidity_error(x.matrix()), 1e-14);
  EXPECT_EQ(rigidity_error(Mat4::Identity()), 0.0);
}

TEST(Se3Rigidity, DetectsEachKindOfDefect) {
  const Mat4 T = random_poses(1, 8)[0].matrix();
  Mat4 reflection = T;
  reflection.col(2).head<3>() *= -1.0;
  EXPECT_EQ(rigidity_error(reflection), kInf);

  Mat4 scaled = T;
  scaled.topLeftCorner<3, 3>() *= 1.01;
  EXPECT_NEAR(rigidity_error(scaled), 0.0201, 1e-12);

  Mat4 sheared = T;
  sheared.topLeftCorner<3, 3>() =
      sheared.topLeftCorner<3, 3>() * (Mat3() << 1, 0.1, 0, 0, 1, 0, 0, 0, 1).finished();
  EXPECT_GT(rigidity_error(sheared), 0.09);

  Mat4 last_row = T;
  last_row(3, 2) = 0.5;
  EXPECT_NEAR(rigidity_error(last_row), 0.5, 1e-15);
  last_row(3, 3) = 2.0;
  EXPECT_NEAR(rigidity_error(last_row), std::hypot(0.5, 1.0), 1e-15);

  Mat4 singular = T;
  singular.topLeftCorner<3, 3>().col(1).setZero();
  EXPECT_EQ(rigidity_error(singular), kInf);

  for (int k = 0; k < 16; ++k) {
    Mat4 bad = T;
    bad(k / 4, k % 4) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(rigidity_error(bad), kInf) << k;
    bad(k / 4, k % 4) = kInf;
    EXPECT_EQ(rigidity_error(bad), kInf) << k;
  }
}

// Poses that differ by round-off quantise to the same bits; the result is a proper rigid transform
// within a grid step of the input.
TEST(Se3Pose, QuantizedMakesRoundOffDifferencesIdentical) {
  Rng rng(9);
  const double grid = 1.0 / (1 << 30);
  int identical = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Pose a;
    a.R = random_rotation(rng);
    a.p = Vec3(rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2));
    // The same pose, moved far away and back: different in the last bits.
    Pose far;
    far.R = so3_exp(Vec3(0.3, -1.1, 2.0));
    far.p = Vec3(2.7, 1.2, -3.0);
    const Pose b = compose(inverse(far), compose(far, a));
    const Pose qa = quantized(a, grid), qb = quantized(b, grid);
    identical += qa.R == qb.R && qa.p == qb.p;
    EXPECT_LT((qa.R.transpose() * qa.R - Mat3::Identity()).norm(), 1e-14);
    EXPECT_LT(so3_distance(qa.R, a.R), 4 * grid);
    EXPECT_LT((qa.p - a.p).norm(), grid);
  }
  EXPECT_GE(identical, 199);
}
}  // namespace
}  // namespace graspecmf::lie
