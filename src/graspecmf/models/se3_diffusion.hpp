#pragma once
// The diffusion of SE(3)-DiffusionFields (Urain et al. 2023; docs/method.md, "Comparison models")
// for any energy E(H, t) over grasp poses: its noise scale, its projected denoising-score-matching
// loss and its annealed Langevin sampler, both in the exponential coordinates φ = (p, ω = Log R).

#include <ATen/core/Generator.h>
#include <ATen/core/Tensor.h>

#include <functional>

#include "graspecmf/flow/pose_batch.hpp"

namespace graspecmf::models {

// E(H, t): the energies [G] of poses H (R [G, 3, 3], p [G, 3]) at diffusion times t [G];
// differentiable in R and p.
using PoseEnergy = std::function<at::Tensor(const flow::PoseBatch&, const at::Tensor&)>;

// σ(t) = sqrt((0.5^{2t} − 1) / (2 ln 0.5)), elementwise: 0.0032 at t = 10⁻⁵, 0.7355 at t = 1.
at::Tensor diffusion_sigma(const at::Tensor& t);

// The projected denoising-score-matching loss of grasps [G]: per grasp t ~ U[10⁻⁵, 1] and
// n ~ N(0, I₆), φ̃ = φ + σ(t) n, and the mean over the 6G numbers of |∇_φ̃ E(Exp(φ̃), t) − n/σ(t)|,
// divided by 10. The gradient goes through the exponential map and keeps its graph, so the loss is
// differentiable in the energy's parameters (gradients are on inside, whatever the caller's
// mode). Draws t, then n, from generator (CPU).
at::Tensor denoising_score_matching_loss(const PoseEnergy& energy, const flow::PoseBatch& grasps,
                                         at::Generator& generator);

struct LangevinSettings {
  int annealed_steps = 70;  // T: time levels τ_i = (T − i)/T + 10⁻³, i = 0 … T − 1
  int final_steps = 50;     // then at τ = 10⁻³ without noise, step 0.003
  int inner_steps = 2;      // updates per time level
};

// Annealed Langevin dynamics from x0: at each level, with step c = 10⁻³ σ(τ)²/σ(10⁻³)² and
// g = ∂E/∂φ, the update δ = −(c/2) g + 0.5 √c ξ (ξ ~ N(0, I₆) from generator; none in the final
// steps) moves p by δ_p and R to Exp(δ_ω) R. No gradients leave it. Throws Error on negative steps.
flow::PoseBatch annealed_langevin(const PoseEnergy& energy, const flow::PoseBatch& x0,
                                  const LangevinSettings& settings, at::Generator& generator);

}  // namespace graspecmf::models
