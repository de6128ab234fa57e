#include "graspecmf/flow/so3.hpp"

#include <ATen/ATen.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "graspecmf/core/error.hpp"
#include "graspecmf/flow/pose_batch.hpp"
#include "graspecmf/lie/so3.hpp"

namespace graspecmf::flow {
namespace {

constexpr double kPi = 3.14159265358979323846;
const auto kF64 = at::TensorOptions().dtype(at::kDouble);

double max_abs(const at::Tensor& x) {
  return x.abs().max().item<double>();
}

// n random unit vectors [n,3].
at::Tensor random_axes(int64_t n, at::Generator& gen, at::ScalarType dtype = at::kDouble) {
  const auto g = at::randn({n, 3}, gen, at::TensorOptions().dtype(dtype));
  return g / g.norm(2, {-1}, true);
}

// Axis-aligned, diagonal and generic unit axes plus `random` random ones.
at::Tensor test_axes(int64_t random, at::Generator& gen) {
  const auto fixed = at::tensor({1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0,  1.0, 0.0, -1.0,
                                 0.0, 1.0, 1.0, 0.0, 1.0, 1.0, 1.0, -1.0, 2.0, 2.0},
                                kF64)
                         .view({-1, 3});
  const auto axes = fixed / fixed.norm(2, {-1}, true);
  return at::cat({axes, random_axes(random, gen)});
}

// Largest |RᵀR − I| and |det R − 1| over a batch of rotations, evaluated in float64.
double rotation_error(const at::Tensor& R) {
  const auto R64 = R.to(at::kDouble);
  const auto eye = at::eye(3, kF64);
  return std::max(max_abs(R64.transpose(-1, -2).matmul(R64) - eye), max_abs(at::det(R64) - 1.0));
}

at::Tensor to_tensor(const lie::Mat3& M) {
  auto T = at::empty({3, 3}, kF64);
  auto a = T.accessor<double, 2>();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = M(i, j);
  return T;
}

lie::Mat3 to_mat3(const at::Tensor& T) {
  const auto a = T.accessor<double, 2>();
  lie::Mat3 M;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) M(i, j) = a[i][j];
  return M;
}

// The unit quaternion (cos θ/2, sin θ/2 · u) is the rotation Exp(θ u); −q is the same rotation.
TEST(FlowSo3, QuaternionsGiveTheirRotations) {
  auto gen = make_generator(7);
  const auto w = at::randn({16, 3}, gen, kF64);
  const auto angle = w.norm(2, {-1}, true);
  const auto q = at::cat({(angle / 2).cos(), (angle / 2).sin() * w / angle}, -1);
  EXPECT_LT(max_abs(quaternion_to_matrix(q) - so3_exp(w)), 1e-12);
  EXPECT_LT(max_abs(quaternion_to_matrix(-q) - so3_exp(w)), 1e-12);
  EXPECT_LT(rotation_error(quaternion_to_matrix(q)), 1e-12);
}

TEST(FlowSo3, HatVeeAndBracket) {
  auto gen = make_generator(1);
  const auto w = at::randn({4, 5, 3}, gen, kF64);
  const auto u = at::randn({4, 5, 3}, gen, kF64);
  const auto W = hat(w);
  const auto U = hat(u);
  ASSERT_EQ(W.sizes(), (std::vector<int64_t>{4, 5, 3, 3}));
  EXPECT_EQ(max_abs(vee(W) - w), 0.0);
  EXPECT_EQ(max_abs(W + W.transpose(-1, -2)), 0.0);
  EXPECT_LT(max_abs(W.matmul(u.unsqueeze(-1)).squeeze(-1) - at::linalg_cross(w, u, -1)), 1e-14);
  EXPECT_LT(max_abs(lie_bracket(w, u) - vee(W.matmul(U) - U.matmul(W))), 1e-14);
  EXPECT_LT(max_abs(hat(lie_bracket(w, u)) - (W.matmul(U) - U.matmul(W))), 1e-14);
}

TEST(FlowSo3, ExpLogRoundTripRandom) {
  auto gen = make_generator(2);
  const int64_t n = 2000;
  const auto angles = at::rand({n, 1}, gen, kF64) * (kPi - 1e-6);
  const auto w = angles * random_axes(n, gen);
  const auto R = so3_exp(w);
  EXPECT_LT(rotation_error(R), 1e-14);
  EXPECT_LT(max_abs(so3_log(R) - w), 1e-12);
  // Rotations of every angle, from vectors longer than π.
  const auto R2 = so3_exp(3.0 * kPi * at::rand({n, 1}, gen, kF64) * random_axes(n, gen));
  const auto w2 = so3_log(R2);
  EXPECT_LE(w2.norm(2, {-1}).max().item<double>(), kPi);
  EXPECT_LT(max_abs(so3_exp(w2) - R2), 1e-12);
}

TEST(FlowSo3, SpecialAngles) {
  auto gen = make_generator(3);
  const auto axes = test_axes(20, gen);
  for (const double angle : {1e-12, 1e-9, 1e-5, 1e-4, 1.0, 2.69, kPi - 1e-4, kPi - 1e-7}) {
    SCOPED_TRACE(angle);
    const auto w = angle * axes;
    const auto R = so3_exp(w);
    EXPECT_LT(rotation_error(R), 1e-14);
    EXPECT_LT(max_abs(so3_log(R) - w) / angle, 1e-12);
    EXPECT_LT(max_abs(so3_exp(so3_log(R)) - R), 1e-14);
    // Never exactly I: to first order R − I = [w]×.
    if (angle <= 1e-5) {
      EXPECT_LT(max_abs(R - at::eye(3, kF64) - hat(w)) / angle, 1e-4);
    }
  }
}

TEST(FlowSo3, ExactHalfTurns) {
  auto gen = make_generator(4);
  const auto axes = test_axes(20, gen);
  // From Exp(π a): sin π rounds to ~1e-16, so the axis sign is arbitrary but the axis is not.
  const auto R = so3_exp(kPi * axes);
  const auto w = so3_log(R);
  const auto plus = (w - kPi * axes).norm(2, {-1});
  const auto minus = (w + kPi * axes).norm(2, {-1});
  EXPECT_LT(at::minimum(plus, minus).max().item<double>(), 1e-12);
  EXPECT_LT(max_abs(so3_exp(w) - R), 1e-14);
  // Exact half-turn matrices 2 a aᵀ − I, symmetric with trace −1 (as stored in ACRONYM files).
  const auto outer = axes.unsqueeze(-1) * axes.unsqueeze(-2);
  const auto H = 2.0 * outer - at::eye(3, kF64);
  const auto wh = so3_log(H);
  const auto plus_h = (wh - kPi * axes).norm(2, {-1});
  const auto minus_h = (wh + kPi * axes).norm(2, {-1});
  EXPECT_LT(at::minimum(plus_h, minus_h).max().item<double>(), 1e-12);
  EXPECT_LT(max_abs(so3_exp(wh) - H), 1e-12);
  // The three diagonal half turns in float32.
  const auto D = at::tensor({1.0F, -1.0F, -1.0F, -1.0F, 1.0F, -1.0F, -1.0F, -1.0F, 1.0F})
                     .view({3, 3})
                     .diag_embed();
  EXPECT_LT(max_abs(so3_log(D).abs() - kPi * at::eye(3, at::kFloat)), 1e-6);
}

TEST(FlowSo3, MatchesLieDoublePrecision) {
  auto gen = make_generator(5);
  const int64_t n = 300;
  auto angles = at::rand({n, 1}, gen, kF64) * kPi;
  angles.narrow(0, 0, 30).fill_(kPi - 1e-6);
  angles.narrow(0, 30, 30).mul_(1e-6);
  const auto w = angles * random_axes(n, gen);
  const auto R = so3_exp(w);
  const auto logs = so3_log(R);
  for (int64_t i = 0; i < n; ++i) {
    const lie::Vec3 wi(w[i][0].item<double>(), w[i][1].item<double>(), w[i][2].item<double>());
    const lie::Mat3 Ri = lie::so3_exp(wi);
    EXPECT_LT(max_abs(R[i] - to_tensor(Ri)), 1e-14);
    const lie::Vec3 li = lie::so3_log(to_mat3(R[i]));
    EXPECT_LT(max_abs(logs[i] - at::tensor({li.x(), li.y(), li.z()}, kF64)), 1e-13);
  }
}

TEST(FlowSo3, Float32RoundTrip) {
  auto gen = make_generator(6);
  const int64_t n = 2000;
  const auto angles = at::rand({n, 1}, gen, at::TensorOptions().dtype(at::kFloat)) * 3.1F;
  const auto w = angles * random_axes(n, gen, at::kFloat);
  const auto R = so3_exp(w);
  ASSERT_EQ(R.scalar_type(), at::kFloat);
  EXPECT_LT(rotation_error(R), 1e-6);
  EXPECT_LT(max_abs(so3_log(R) - w), 2e-5);
  const auto tiny = so3_exp(at::tensor({1e-9F, 0.0F, 0.0F}));
  EXPECT_FLOAT_EQ(tiny[2][1].item<float>(), 1e-9F);
}

TEST(FlowSo3, GradientsFiniteAtIdentity) {
  auto gen = make_generator(7);
  const auto C = at::randn({3, 3}, gen, kF64);
  // d/dw Σ C ⊙ Exp(w) at w = 0 is Σ C ⊙ [e_k]× = 2 vee(C).
  for (const double scale : {0.0, 1e-9}) {
    auto w = (scale * at::ones({3}, kF64)).requires_grad_(true);
    (so3_exp(w) * C).sum().backward();
    ASSERT_TRUE(at::isfinite(w.grad()).all().item<bool>());
    EXPECT_LT(max_abs(w.grad() - 2.0 * vee(C)), 1e-8);
  }
  auto R = at::eye(3, kF64).requires_grad_(true);
  so3_log(R).sum().backward();
  EXPECT_TRUE(at::isfinite(R.grad()).all().item<bool>());
}

TEST(FlowSo3, RejectsBadInput) {
  EXPECT_THROW(hat(at::zeros({2, 4})), Error);
  EXPECT_THROW(vee(at::zeros({3, 2})), Error);
  EXPECT_THROW(so3_exp(at::zeros({3}, at::kInt)), Error);
  EXPECT_THROW(so3_log(at::zeros({3})), Error);
  EXPECT_THROW(lie_bracket(at::zeros({3}), at::zeros({2})), Error);
}

}  // namespace
}  // namespace graspecmf::flow
