#include "graspecmf/flow/sampler.hpp"

#include <ATen/ATen.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "graspecmf/core/error.hpp"
#include "graspecmf/flow/path.hpp"
#include "graspecmf/flow/pose_batch.hpp"
#include "graspecmf/flow/prior.hpp"
#include "graspecmf/flow/so3.hpp"

namespace graspecmf::flow {
namespace {

using Field = std::pair<at::Tensor, at::Tensor>;
const auto kF64 = at::TensorOptions().dtype(at::kDouble);

double max_abs(const at::Tensor& x) {
  return x.abs().max().item<double>();
}

// Largest entry of |R − R'| and |p − p'|.
double pose_error(const PoseBatch& a, const PoseBatch& b) {
  return std::max(max_abs(a.R - b.R), max_abs(a.p - b.p));
}

at::Tensor dot_last(const at::Tensor& a, const at::Tensor& b) {
  return (a * b).sum(-1, /*keepdim=*/true);
}

// A smooth, time-dependent, state-dependent field built from R's columns r1, r2, r3, p and t, so
// it is rotation-equivariant: f(gR, gp, t) = g f(R, p, t). Its body velocity Rᵀω depends on Rᵀp
// and t and does not commute with itself along the path.
Field equivariant_field(const PoseBatch& x, const at::Tensor& t) {
  const auto r1 = x.R.select(-1, 0);
  const auto r2 = x.R.select(-1, 1);
  const auto r3 = x.R.select(-1, 2);
  const auto& p = x.p;
  const auto tc = t.unsqueeze(-1);
  const auto omega = 0.6 * (1.0 + tc) * at::linalg_cross(r1, p, -1) +
                     1.2 * (3.0 * tc + 0.4).sin() * r2 + 0.5 * dot_last(p, r3) * r1;
  const auto v = 0.8 * r3 - 0.3 * p + 0.4 * tc * at::linalg_cross(r2, p, -1);
  return Field{omega, v};
}

// The equivariant field plus terms along fixed world directions (not equivariant).
Field general_field(const PoseBatch& x, const at::Tensor& t) {
  auto [omega, v] = equivariant_field(x, t);
  const auto ez = at::tensor({0.0, 0.0, 1.0}, x.R.options());
  const auto ex = at::tensor({1.0, 0.0, 0.0}, x.R.options());
  const auto tc = t.unsqueeze(-1);
  omega = omega + 0.7 * (2.0 * tc).cos() * ez +
          0.5 * at::linalg_cross(ex.expand_as(omega), x.R.select(-1, 2), -1);
  v = v + 0.5 * tc.sin() * ex;
  return Field{omega, v};
}

PoseBatch start_poses(int64_t n, at::ScalarType dtype, uint64_t seed = 41) {
  auto gen = make_generator(seed);
  return sample_prior(n, 1.0, gen, dtype);
}

TEST(FlowSampler, SolverNames) {
  for (const auto solver : {Solver::euler, Solver::heun, Solver::rkmk4}) {
    EXPECT_EQ(parse_solver(solver_name(solver)), solver);
  }
  EXPECT_EQ(parse_solver("rkmk4"), Solver::rkmk4);
  EXPECT_THROW(parse_solver("rk4"), Error);
  EXPECT_THROW(parse_solver("Euler"), Error);
  EXPECT_THROW(parse_solver(""), Error);
}

// A constant body velocity K and linear velocity v: every solver is exact, R(1) = R0 Exp(K).
TEST(FlowSampler, ConstantBodyVelocityIsExact) {
  auto gen = make_generator(42);
  const auto x0 = start_poses(16, at::kDouble);
  const auto K = 2.0 * at::randn({16, 3}, gen, kF64);
  const auto v = at::randn({16, 3}, gen, kF64);
  const VectorField field = [&](const PoseBatch& x, const at::Tensor&) {
    return Field{x.R.matmul(K.unsqueeze(-1)).squeeze(-1), v};
  };
  const PoseBatch exact{x0.R.matmul(so3_exp(K)), x0.p + v};
  for (const auto solver : {Solver::euler, Solver::heun, Solver::rkmk4}) {
    SCOPED_TRACE(solver_name(solver));
    EXPECT_LT(pose_error(integrate(field, x0, solver, 3), exact), 1e-12);
  }
}

// The training target of the geodesic path, a constant spatial velocity, carries x0 to x1 under
// every solver (exactly: Exp(h ω) R = R Exp(h Rᵀ ω)).
TEST(FlowSampler, FollowsTheTrainingPath) {
  const auto x0 = start_poses(16, at::kDouble, 44);
  const auto x1 = start_poses(16, at::kDouble, 45);
  const auto target = geodesic_path(x0, x1, at::zeros({16}, kF64));
  const VectorField field = [&](const PoseBatch&, const at::Tensor&) {
    return Field{target.omega, target.v};
  };
  for (const auto solver : {Solver::euler, Solver::heun, Solver::rkmk4}) {
    SCOPED_TRACE(solver_name(solver));
    EXPECT_LT(pose_error(integrate(field, x0, solver, 4), x1), 1e-12);
  }
}

// Errors against a fine RKMK4 reference shrink by 2^order per halving of the step.
TEST(FlowSampler, ConvergenceOrder) {
  const auto x0 = start_poses(16, at::kDouble);
  const auto reference = integrate(general_field, x0, Solver::rkmk4, 512);
  struct Case {
    Solver solver;
    int coarsest;
    double lo, hi;
  };
  for (const Case& c : {Case{Solver::euler, 16, 1.8, 2.2}, Case{Solver::heun, 8, 3.5, 4.5},
                        Case{Solver::rkmk4, 4, 12.0, 20.0}}) {
    std::vector<double> errors;
    for (int steps = c.coarsest; steps <= 8 * c.coarsest; steps *= 2) {
      errors.push_back(pose_error(integrate(general_field, x0, c.solver, steps), reference));
    }
    std::cout << "[ ratios   ] " << solver_name(c.solver) << " from " << c.coarsest << " steps:";
    for (std::size_t i = 1; i < errors.size(); ++i) std::cout << ' ' << errors[i - 1] / errors[i];
    std::cout << "  (errors " << errors.front() << " .. " << errors.back() << ")\n";
    // The finer halvings are in the asymptotic regime.
    for (std::size_t i = 2; i < errors.size(); ++i) {
      SCOPED_TRACE(solver_name(c.solver) + " halving " + std::to_string(i));
      const double ratio = errors[i - 1] / errors[i];
      EXPECT_GE(ratio, c.lo);
      EXPECT_LE(ratio, c.hi);
    }
  }
}

TEST(FlowSampler, RotationsStayOrthonormal) {
  for (const auto dtype : {at::kFloat, at::kDouble}) {
    const auto x0 = start_poses(256, dtype);
    for (const auto solver : {Solver::euler, Solver::heun, Solver::rkmk4}) {
      SCOPED_TRACE(solver_name(solver));
      const auto x = integrate(general_field, x0, solver, 20);
      ASSERT_EQ(x.R.scalar_type(), dtype);
      ASSERT_EQ(x.p.scalar_type(), dtype);
      // Measured in float64, so that the check adds no rounding of its own.
      const auto R = x.R.to(at::kDouble);
      const double tol = dtype == at::kFloat ? 1e-6 : 1e-13;
      EXPECT_LT(max_abs(R.transpose(1, 2).matmul(R) - at::eye(3, kF64)), tol);
      EXPECT_LT(max_abs(at::det(R) - 1.0), tol);
    }
  }
}

// Integrating from g·x0 gives g·x(1) for an equivariant field, in float32.
TEST(FlowSampler, IntegratorsAreEquivariant) {
  const auto x0 = start_poses(64, at::kFloat);
  auto gen = make_generator(43);
  const auto rotations = sample_prior(3, 0.0, gen).R;
  for (const auto solver : {Solver::euler, Solver::heun, Solver::rkmk4}) {
    SCOPED_TRACE(solver_name(solver));
    const auto x = integrate(equivariant_field, x0, solver, 20);
    for (int64_t i = 0; i < rotations.size(0); ++i) {
      const auto g = rotations[i];
      const PoseBatch gx0{g.matmul(x0.R), x0.p.matmul(g.t())};
      const auto gx = integrate(equivariant_field, gx0, solver, 20);
      EXPECT_LT(pose_error(gx, PoseBatch{g.matmul(x.R), x.p.matmul(g.t())}), 1e-5);
    }
  }
}

TEST(FlowSampler, GuidedFieldMixesConditionedAndNull) {
  const auto x0 = start_poses(8, at::kDouble);
  int calls = 0;
  // Conditioned: the general field; null: the equivariant one.
  const ConditionalField conditional = [&](const PoseBatch& x, const at::Tensor& t,
                                           const at::Tensor& keep) {
    ++calls;
    EXPECT_EQ(x.R.size(0), 16);
    EXPECT_TRUE(at::equal(keep, at::cat({at::ones({8}, kF64), at::zeros({8}, kF64)})));
    const auto [wa, va] = general_field(x, t);
    const auto [wb, vb] = equivariant_field(x, t);
    const auto k = keep.unsqueeze(-1);
    return Field{k * wa + (1.0 - k) * wb, k * va + (1.0 - k) * vb};
  };
  const auto t = at::full({8}, 0.3, kF64);
  const auto [wa, va] = general_field(x0, t);
  const auto [wb, vb] = equivariant_field(x0, t);
  const auto [w1, v1] = guided_field(conditional, 1.0)(x0, t);
  const auto [w0, v0] = guided_field(conditional, 0.0)(x0, t);
  const auto [w2, v2] = guided_field(conditional, 2.0)(x0, t);
  EXPECT_EQ(calls, 3);
  EXPECT_LT(max_abs(w1 - wa) + max_abs(v1 - va), 1e-15);
  EXPECT_LT(max_abs(w0 - wb) + max_abs(v0 - vb), 1e-15);
  EXPECT_LT(max_abs(w2 - (2.0 * wa - wb)) + max_abs(v2 - (2.0 * va - vb)), 1e-14);
  const auto guided = integrate(guided_field(conditional, 1.0), x0, Solver::rkmk4, 5);
  EXPECT_LT(pose_error(guided, integrate(general_field, x0, Solver::rkmk4, 5)), 1e-15);
}

TEST(FlowSampler, RecordsNoGradientAndRejectsBadInput) {
  const auto x0 = start_poses(4, at::kDouble);
  const auto scale = at::ones({1}, kF64).requires_grad_(true);
  const VectorField scaled = [&](const PoseBatch& x, const at::Tensor& t) {
    const auto [omega, v] = equivariant_field(x, t);
    return Field{scale * omega, v};
  };
  EXPECT_FALSE(integrate(scaled, x0, Solver::heun, 2).R.requires_grad());
  EXPECT_THROW(integrate(equivariant_field, x0, Solver::euler, 0), Error);
  const VectorField short_rows = [](const PoseBatch& x, const at::Tensor&) {
    return Field{x.p.narrow(0, 0, 1), x.p};
  };
  EXPECT_THROW(integrate(short_rows, x0, Solver::euler, 1), Error);
  const VectorField single = [](const PoseBatch& x, const at::Tensor&) {
    return Field{x.p.to(at::kFloat), x.p};
  };
  EXPECT_THROW(integrate(single, x0, Solver::euler, 1), Error);
  EXPECT_THROW(
      integrate(equivariant_field, PoseBatch{x0.R, x0.p.narrow(0, 0, 2)}, Solver::euler, 1), Error);
}

}  // namespace
}  // namespace graspecmf::flow
