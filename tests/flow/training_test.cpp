// The training side of the flow: prior, geodesic path and targets, loss, guidance-dropout mask.

#include <ATen/ATen.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "graspecmf/core/error.hpp"
#include "graspecmf/flow/loss.hpp"
#include "graspecmf/flow/path.hpp"
#include "graspecmf/flow/pose_batch.hpp"
#include "graspecmf/flow/prior.hpp"
#include "graspecmf/flow/so3.hpp"

namespace graspecmf::flow {
namespace {

constexpr double kPi = 3.14159265358979323846;
const auto kF64 = at::TensorOptions().dtype(at::kDouble);

double max_abs(const at::Tensor& x) {
  return x.abs().max().item<double>();
}

// Largest |RᵀR − I| and |det R − 1| over a batch of rotations, evaluated in float64.
double rotation_error(const at::Tensor& R) {
  const auto R64 = R.to(at::kDouble);
  const auto eye = at::eye(3, kF64);
  return std::max(max_abs(R64.transpose(-1, -2).matmul(R64) - eye), max_abs(at::det(R64) - 1.0));
}

// Expects the sample mean of x (any shape, samples along dim 0) to equal `expected` within 4
// standard errors (estimated from the sample), elementwise.
void expect_mean(const at::Tensor& x, double expected, const char* what) {
  const auto mean = x.mean(0);
  const auto standard_error = x.std(0) / std::sqrt(static_cast<double>(x.size(0)));
  EXPECT_TRUE(((mean - expected).abs() < 4.0 * standard_error).all().item<bool>())
      << what << ": mean " << mean << " expected " << expected;
}

TEST(FlowPrior, RotationsAndShapes) {
  for (const auto dtype : {at::kFloat, at::kDouble}) {
    auto gen = make_generator(11);
    const auto x = sample_prior(500, 1.0, gen, dtype);
    ASSERT_EQ(x.R.sizes(), (std::vector<int64_t>{500, 3, 3}));
    ASSERT_EQ(x.p.sizes(), (std::vector<int64_t>{500, 3}));
    ASSERT_EQ(x.R.scalar_type(), dtype);
    ASSERT_EQ(x.p.scalar_type(), dtype);
    EXPECT_LT(rotation_error(x.R), dtype == at::kFloat ? 1e-6 : 1e-14);
  }
}

TEST(FlowPrior, HaarAndGaussianStatistics) {
  auto gen = make_generator(12);
  const int64_t n = 20000;
  const auto x = sample_prior(n, 2.0, gen, at::kDouble);
  // Haar: every entry is a coordinate of a uniform unit vector, so E[R_ij] = 0, E[R_ij²] = 1/3;
  // the character satisfies E[tr R] = 0 and E[(tr R)²] = 1.
  expect_mean(x.R, 0.0, "R_ij");
  expect_mean(x.R.square(), 1.0 / 3.0, "R_ij^2");
  const auto trace = x.R.diagonal(0, 1, 2).sum(-1);
  expect_mean(trace, 0.0, "tr R");
  expect_mean(trace.square(), 1.0, "(tr R)^2");
  // Positions: N(0, 2² I).
  expect_mean(x.p, 0.0, "p");
  expect_mean(x.p.square(), 4.0, "p^2");
  expect_mean(x.p.prod(-1), 0.0, "p_x p_y p_z");
}

TEST(FlowPrior, ReproducibleBySeed) {
  auto a = make_generator(13);
  auto b = make_generator(13);
  auto c = make_generator(14);
  const auto xa = sample_prior(100, 1.0, a);
  const auto xb = sample_prior(100, 1.0, b);
  const auto xc = sample_prior(100, 1.0, c);
  EXPECT_TRUE(at::equal(xa.R, xb.R));
  EXPECT_TRUE(at::equal(xa.p, xb.p));
  EXPECT_FALSE(at::equal(xa.R, xc.R));
  // The generator advances: a second draw differs from the first.
  EXPECT_FALSE(at::equal(sample_prior(100, 1.0, a).R, xa.R));
}

TEST(FlowPrior, RejectsBadArguments) {
  auto gen = make_generator(15);
  EXPECT_THROW(sample_prior(-1, 1.0, gen), Error);
  EXPECT_THROW(sample_prior(10, -1.0, gen), Error);
  EXPECT_THROW(sample_prior(10, NAN, gen), Error);
  EXPECT_THROW(sample_prior(10, 1.0, gen, at::kInt), Error);
  EXPECT_EQ(sample_prior(0, 1.0, gen).R.size(0), 0);
}

// Pairs of prior samples with a few exact half turns R0ᵀ R1 among them.
struct Pair {
  PoseBatch x0, x1;
};
Pair random_pair(int64_t n, uint64_t seed) {
  auto gen = make_generator(seed);
  Pair pair{sample_prior(n, 1.0, gen, at::kDouble), sample_prior(n, 1.0, gen, at::kDouble)};
  const auto half_turn = at::tensor({1.0, -1.0, -1.0}, kF64).diag();
  pair.x1.R.narrow(0, 0, 2).copy_(pair.x0.R.narrow(0, 0, 2).matmul(half_turn));
  return pair;
}

TEST(FlowPath, EndpointsAndHalfTurns) {
  const auto [x0, x1] = random_pair(64, 21);
  const auto start = geodesic_path(x0, x1, at::zeros({64}, kF64));
  const auto end = geodesic_path(x0, x1, at::ones({64}, kF64));
  EXPECT_LT(max_abs(start.x_t.R - x0.R), 1e-15);
  EXPECT_LT(max_abs(start.x_t.p - x0.p), 1e-15);
  EXPECT_LT(max_abs(end.x_t.R - x1.R), 1e-12);
  EXPECT_LT(max_abs(end.x_t.p - x1.p), 1e-15);
  // The half turns about R0's x axis: ω = ±π · (first column of R0).
  const auto w = end.omega.narrow(0, 0, 2);
  const auto axis = x0.R.narrow(0, 0, 2).select(-1, 0);
  EXPECT_LT(max_abs(w.norm(2, {-1}) - kPi), 1e-12);
  EXPECT_LT(max_abs(at::linalg_cross(w, axis, -1)), 1e-12);
}

TEST(FlowPath, TargetsAreTheSpatialVelocity) {
  const auto [x0, x1] = random_pair(64, 22);
  const auto xi = so3_log(x0.R.transpose(1, 2).matmul(x1.R));
  const auto first = geodesic_path(x0, x1, at::zeros({64}, kF64));
  for (const double t : {0.1, 0.5, 0.93}) {
    SCOPED_TRACE(t);
    const auto tt = at::full({64}, t, kF64);
    const auto point = geodesic_path(x0, x1, tt);
    // Constant along the path, equal to R_t ξ, and v = p1 − p0.
    EXPECT_LT(max_abs(point.omega - first.omega), 1e-15);
    EXPECT_LT(max_abs(point.x_t.R.matmul(xi.unsqueeze(-1)).squeeze(-1) - point.omega), 1e-12);
    EXPECT_LT(max_abs(point.v - (x1.p - x0.p)), 1e-15);
    // Central differences in t: Ṙ_t = [ω]× R_t and ṗ_t = v.
    const double dt = 1e-5;
    const auto ahead = geodesic_path(x0, x1, tt + dt);
    const auto behind = geodesic_path(x0, x1, tt - dt);
    const auto R_dot = (ahead.x_t.R - behind.x_t.R) / (2.0 * dt);
    const auto p_dot = (ahead.x_t.p - behind.x_t.p) / (2.0 * dt);
    EXPECT_LT(max_abs(R_dot - hat(point.omega).matmul(point.x_t.R)), 1e-8);
    EXPECT_LT(max_abs(p_dot - point.v), 1e-9);
  }
}

TEST(FlowPath, Float32AndBadInput) {
  auto gen = make_generator(23);
  const auto x0 = sample_prior(8, 1.0, gen);
  const auto x1 = sample_prior(8, 1.0, gen);
  const auto point = geodesic_path(x0, x1, at::full({8}, 0.5F));
  EXPECT_EQ(point.x_t.R.scalar_type(), at::kFloat);
  EXPECT_LT(rotation_error(point.x_t.R), 1e-6);
  EXPECT_THROW(geodesic_path(x0, x1, at::full({7}, 0.5F)), Error);
  EXPECT_THROW(geodesic_path(x0, x1, at::full({8}, 0.5, kF64)), Error);
  EXPECT_THROW(geodesic_path(x0, PoseBatch{x1.R, x1.p.narrow(0, 0, 4)}, at::full({8}, 0.5F)),
               Error);
}

TEST(FlowLoss, MeanSquaredErrorOverSixNumbers) {
  const auto omega = at::tensor({1.0, 2.0, 3.0, -1.0, 0.0, 0.5}, kF64).view({2, 3});
  const auto v = at::tensor({0.0, 1.0, -2.0, 4.0, 0.25, 0.0}, kF64).view({2, 3});
  EXPECT_EQ(flow_matching_loss(omega, v, omega, v).item<double>(), 0.0);
  // Errors: ω row 0 (1, 0, 0), row 1 (0, 0, −0.5); v row 0 (0, 0, 2), row 1 (−1, 0, 0).
  const auto omega_target = at::tensor({0.0, 2.0, 3.0, -1.0, 0.0, 1.0}, kF64).view({2, 3});
  const auto v_target = at::tensor({0.0, 1.0, -4.0, 5.0, 0.25, 0.0}, kF64).view({2, 3});
  const double expected = (1.0 + 0.25 + 4.0 + 1.0) / 12.0;
  EXPECT_NEAR(flow_matching_loss(omega, v, omega_target, v_target).item<double>(), expected, 1e-15);
  // Differentiable in the predictions: d/dω = 2 (ω − ω*) / 12.
  auto omega_pred = omega.clone().requires_grad_(true);
  flow_matching_loss(omega_pred, v, omega_target, v_target).backward();
  EXPECT_LT(max_abs(omega_pred.grad() - (omega - omega_target) / 6.0), 1e-15);
  EXPECT_THROW(flow_matching_loss(omega, v.narrow(0, 0, 1), omega, v), Error);
  EXPECT_THROW(flow_matching_loss(omega, v, omega.to(at::kFloat), v), Error);
}

TEST(FlowLoss, GuidanceKeepMask) {
  auto gen = make_generator(31);
  const int64_t n = 100000;
  const auto mask = cfg_keep_mask(n, 0.2, gen);
  ASSERT_EQ(mask.scalar_type(), at::kFloat);
  ASSERT_EQ(mask.sizes(), (std::vector<int64_t>{n}));
  EXPECT_TRUE(((mask == 0.0) | (mask == 1.0)).all().item<bool>());
  // Mean 0.8 with standard error sqrt(0.8 · 0.2 / n) = 0.00126.
  EXPECT_NEAR(mask.to(at::kDouble).mean().item<double>(), 0.8, 4.0 * 0.00126);
  auto a = make_generator(32);
  auto b = make_generator(32);
  EXPECT_TRUE(at::equal(cfg_keep_mask(1000, 0.2, a, at::kDouble),
                        cfg_keep_mask(1000, 0.2, b, at::kDouble)));
  EXPECT_TRUE((cfg_keep_mask(1000, 0.0, gen) == 1.0).all().item<bool>());
  EXPECT_TRUE((cfg_keep_mask(1000, 1.0, gen) == 0.0).all().item<bool>());
  EXPECT_THROW(cfg_keep_mask(10, 1.5, gen), Error);
  EXPECT_THROW(cfg_keep_mask(10, NAN, gen), Error);
  EXPECT_THROW(cfg_keep_mask(-1, 0.2, gen), Error);
}

}  // namespace
}  // namespace graspecmf::flow
