#include "graspecmf/flow/sampler.hpp"

#include <ATen/ATen.h>

#include <cmath>

#include "graspecmf/core/error.hpp"
#include "graspecmf/flow/so3.hpp"

namespace graspecmf::flow {

namespace {

// The field at one stage, with the angular velocity in the body frame of the stage rotation.
struct Velocity {
  at::Tensor K;  // Rᵀ ω, [B,3]
  at::Tensor v;  // [B,3]
};

// Evaluates the field on float64 stage poses: it hands the field the poses rounded to `dtype` and
// returns float64 velocities.
class Stepper {
 public:
  Stepper(const VectorField& field, int64_t batch, at::ScalarType dtype)
      : field_(field), batch_(batch), dtype_(dtype) {}

  Velocity operator()(const at::Tensor& R, const at::Tensor& p, double t) const {
    const PoseBatch x{R.to(dtype_), p.to(dtype_)};
    const auto [omega, v] = field_(x, at::full({batch_}, t, x.R.options()));
    for (const auto* y : {&omega, &v}) {
      if (!y->defined() || y->dim() != 2 || y->size(0) != batch_ || y->size(1) != 3 ||
          y->scalar_type() != dtype_) {
        throw Error(
            "integrate: the vector field must return two [B,3] tensors of the poses' dtype");
      }
    }
    return {R.transpose(1, 2).matmul(omega.to(at::kDouble).unsqueeze(-1)).squeeze(-1),
            v.to(at::kDouble)};
  }

 private:
  const VectorField& field_;
  int64_t batch_;
  at::ScalarType dtype_;
};

// R Exp(U): the rotation moved by the body-frame increment U.
at::Tensor move(const at::Tensor& R, const at::Tensor& U) {
  return R.matmul(so3_exp(U));
}

void euler_step(const Stepper& f, PoseBatch& x, double t, double h) {
  const auto k1 = f(x.R, x.p, t);
  x.R = move(x.R, h * k1.K);
  x.p = x.p + h * k1.v;
}

// The trapezoidal rule in the algebra: no commutator term is needed for order 2, because the
// first one of dexp⁻¹ enters the local error at O(h³).
void heun_step(const Stepper& f, PoseBatch& x, double t, double h) {
  const auto k1 = f(x.R, x.p, t);
  const auto k2 = f(move(x.R, h * k1.K), x.p + h * k1.v, t + h);
  x.R = move(x.R, 0.5 * h * (k1.K + k2.K));
  x.p = x.p + 0.5 * h * (k1.v + k2.v);
}

// RKMK4 as in METHOD §6 ([A, B] in vector form is a × b); positions by classical RK4.
void rkmk4_step(const Stepper& f, PoseBatch& x, double t, double h) {
  const auto k1 = f(x.R, x.p, t);
  const auto k2 = f(move(x.R, 0.5 * h * k1.K), x.p + 0.5 * h * k1.v, t + 0.5 * h);
  const auto u3 = 0.5 * h * k2.K + (h * h / 24.0) * lie_bracket(k1.K, k2.K);
  const auto k3 = f(move(x.R, u3), x.p + 0.5 * h * k2.v, t + 0.5 * h);
  const auto u4 = h * k3.K + (h * h / 6.0) * lie_bracket(k1.K, k3.K);
  const auto k4 = f(move(x.R, u4), x.p + h * k3.v, t + h);
  const auto i2 = (2.0 * k2.K + 2.0 * k3.K - k4.K - 3.0 * k1.K) / h;
  const auto u = (h / 6.0) * (k1.K + 2.0 * k2.K + 2.0 * k3.K + k4.K);
  const auto corrected = u + (h / 4.0) * lie_bracket(k1.K, u) + (h * h / 24.0) * lie_bracket(i2, u);
  x.R = move(x.R, corrected);
  x.p = x.p + (h / 6.0) * (k1.v + 2.0 * k2.v + 2.0 * k3.v + k4.v);
}

}  // namespace

Solver parse_solver(const std::string& name) {
  if (name == "euler") return Solver::euler;
  if (name == "heun") return Solver::heun;
  if (name == "rkmk4") return Solver::rkmk4;
  throw Error("unknown ODE solver '" + name + "' (expected euler, heun or rkmk4)");
}

std::string solver_name(Solver solver) {
  switch (solver) {
    case Solver::euler:
      return "euler";
    case Solver::heun:
      return "heun";
    case Solver::rkmk4:
      return "rkmk4";
  }
  throw Error("solver_name: invalid solver");
}

PoseBatch integrate(const VectorField& field, const PoseBatch& x0, Solver solver, int steps) {
  check_pose_batch(x0, "integrate");
  if (steps < 1) throw Error("integrate: the number of steps must be >= 1");
  const at::NoGradGuard no_grad;
  const auto dtype = x0.R.scalar_type();
  const Stepper f(field, x0.R.size(0), dtype);
  const double h = 1.0 / steps;
  PoseBatch x{x0.R.to(at::kDouble), x0.p.to(at::kDouble)};
  for (int k = 0; k < steps; ++k) {
    const double t = static_cast<double>(k) / steps;
    switch (solver) {
      case Solver::euler:
        euler_step(f, x, t, h);
        break;
      case Solver::heun:
        heun_step(f, x, t, h);
        break;
      case Solver::rkmk4:
        rkmk4_step(f, x, t, h);
        break;
    }
  }
  return PoseBatch{x.R.to(dtype), x.p.to(dtype)};
}

VectorField guided_field(ConditionalField conditional_field, double w) {
  if (!std::isfinite(w)) throw Error("guided_field: the guidance weight must be finite");
  return [f = std::move(conditional_field), w](const PoseBatch& x, const at::Tensor& t) {
    const int64_t n = x.R.size(0);
    const PoseBatch doubled{at::cat({x.R, x.R}), at::cat({x.p, x.p})};
    const auto keep = at::cat({at::ones({n}, t.options()), at::zeros({n}, t.options())});
    const auto [omega, v] = f(doubled, at::cat({t, t}), keep);
    const auto mix = [n, w](const at::Tensor& y) {
      return (1.0 - w) * y.narrow(0, n, n) + w * y.narrow(0, 0, n);
    };
    return std::make_pair(mix(omega), mix(v));
  };
}

}  // namespace graspecmf::flow
