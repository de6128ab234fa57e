#pragma once
// Sampling (METHOD §6): integrating a vector field on SO(3) × R³ from t = 0 to 1 with Lie-group
// integrators that move rotations by right-multiplication R ← R Exp(U) with body-frame U, and
// classifier-free guidance that runs the conditioned and the null pass in one batch.

#include <ATen/core/Tensor.h>

#include <functional>
#include <string>
#include <utility>

#include "graspecmf/flow/pose_batch.hpp"

namespace graspecmf::flow {

// A vector field at poses x (B of them) and times t ([B], dtype of x): returns (ω, v), each [B,3],
// ω the spatial angular velocity (Ṙ = [ω]× R) and v = ṗ.
using VectorField =
    std::function<std::pair<at::Tensor, at::Tensor>(const PoseBatch& x, const at::Tensor& t)>;
// A field with a condition switch: keep_mask [B] (dtype of x) is 1 where the grasp uses the
// condition z and 0 where it uses the null condition.
using ConditionalField = std::function<std::pair<at::Tensor, at::Tensor>(
    const PoseBatch& x, const at::Tensor& t, const at::Tensor& keep_mask)>;

// euler: Lie–Euler, order 1, 1 field evaluation per step. heun: the explicit trapezoidal RKMK
// method, order 2, 2 evaluations. rkmk4: Runge–Kutta–Munthe-Kaas with commutator corrections,
// order 4, 4 evaluations.
enum class Solver { euler, heun, rkmk4 };

// "euler", "heun" or "rkmk4" → the solver; throws Error naming the valid names otherwise.
Solver parse_solver(const std::string& name);
// The name parse_solver accepts for solver.
std::string solver_name(Solver solver);

// Integrates ẋ = field(x, t) from x0 at t = 0 to t = 1 in `steps` equal steps (no gradients are
// recorded). Rotations stay on SO(3) to rounding: every update is a product with an Exp, and the
// state is kept in float64 (the field sees it rounded to x0's dtype, as is the result). The field
// is evaluated at times k/steps plus the stage offsets. Throws Error for steps < 1 or a bad x0,
// and if the field returns tensors that are not [B,3] in the dtype of x0.
PoseBatch integrate(const VectorField& field, const PoseBatch& x0, Solver solver, int steps);

// The classifier-free-guided field (1 − w)·f(∅) + w·f(z) for ω and v. Each evaluation calls
// conditional_field once on the batch concatenated with itself and keep_mask = [1…1, 0…0]: the
// first half is conditioned, the second half is null. w = 1 is the conditioned field, w = 0 the
// null one.
VectorField guided_field(ConditionalField conditional_field, double w);

}  // namespace graspecmf::flow
