#include "graspecmf/models/se3_diffusion.hpp"

#include <ATen/ATen.h>
#include <torch/autograd.h>
#include <torch/utils.h>

#include <cmath>

#include "graspecmf/core/error.hpp"
#include "graspecmf/flow/so3.hpp"

namespace graspecmf::models {
namespace {

constexpr double kMinTime = 1e-5;
constexpr double kFinalTime = 1e-3;
constexpr double kFinalStep = 0.003;

// ∂E/∂φ [G, 6] (position part first) at φ = (p, ω) [G, 6] and times t, through H = (Exp ω, p).
// With create_graph the gradient stays differentiable in the energy's parameters.
at::Tensor energy_gradient(const PoseEnergy& energy, const at::Tensor& phi, const at::Tensor& t,
                           bool create_graph) {
  const flow::PoseBatch h{flow::so3_exp(phi.slice(1, 3, 6)), phi.slice(1, 0, 3)};
  const at::Tensor e = energy(h, t);
  return torch::autograd::grad({e.sum()}, {phi}, {}, /*retain_graph=*/create_graph,
                               create_graph)[0];
}

}  // namespace

at::Tensor diffusion_sigma(const at::Tensor& t) {
  return ((at::pow(0.5, 2 * t) - 1) / (2 * std::log(0.5))).sqrt();
}

at::Tensor denoising_score_matching_loss(const PoseEnergy& energy, const flow::PoseBatch& grasps,
                                         at::Generator& generator) {
  flow::check_pose_batch(grasps, "denoising_score_matching_loss");
  const int64_t g = grasps.R.size(0);
  const auto options = grasps.p.options();
  const auto cpu = at::TensorOptions().dtype(grasps.p.scalar_type());
  const auto t = (kMinTime + (1 - kMinTime) * at::rand({g}, generator, cpu)).to(options.device());
  const auto noise = at::randn({g, 6}, generator, cpu).to(options.device());
  const auto sigma = diffusion_sigma(t).unsqueeze(1);
  const auto phi = at::cat({grasps.p, flow::so3_log(grasps.R)}, 1).detach();
  // The loss needs ∂E/∂φ̃ also where the caller turned gradients off (a validation loss).
  torch::AutoGradMode enable(true);
  const auto noisy = (phi + sigma * noise).requires_grad_(true);
  const auto gradient = energy_gradient(energy, noisy, t, /*create_graph=*/true);
  return (gradient - noise / sigma).abs().mean() / 10;
}

flow::PoseBatch annealed_langevin(const PoseEnergy& energy, const flow::PoseBatch& x0,
                                  const LangevinSettings& settings, at::Generator& generator) {
  flow::check_pose_batch(x0, "annealed_langevin");
  if (settings.annealed_steps < 0 || settings.final_steps < 0 || settings.inner_steps < 0) {
    throw Error("annealed_langevin: step counts must not be negative");
  }
  const int64_t g = x0.R.size(0);
  const auto options = x0.p.options();
  const auto cpu = at::TensorOptions().dtype(x0.p.scalar_type());
  const double sigma_final =
      diffusion_sigma(at::tensor(kFinalTime, at::TensorOptions().dtype(at::kDouble)))
          .item<double>();
  flow::PoseBatch x{x0.R.detach(), x0.p.detach()};
  // One update at time level tau with step c; noise when `noisy`.
  const auto update = [&](double tau, double c, bool noisy) {
    const auto phi = at::cat({x.p, at::zeros({g, 3}, options)}, 1).requires_grad_(true);
    // ω = 0 at the current rotation: H = (Exp(ω) R, p), so ∂E/∂ω is the gradient in the frame on
    // the left, where the update Exp(δ_ω) R applies it.
    const PoseEnergy at_x = [&](const flow::PoseBatch& h, const at::Tensor& t) {
      return energy({h.R.matmul(x.R), h.p}, t);
    };
    at::Tensor gradient;
    {
      torch::AutoGradMode enable(true);
      gradient = energy_gradient(at_x, phi, at::full({g}, tau, options), false).detach();
    }
    auto delta = -0.5 * c * gradient;
    if (noisy)
      delta = delta + 0.5 * std::sqrt(c) * at::randn({g, 6}, generator, cpu).to(options.device());
    x = {flow::so3_exp(delta.slice(1, 3, 6)).matmul(x.R), x.p + delta.slice(1, 0, 3)};
  };
  const int steps = settings.annealed_steps;
  for (int i = 0; i < steps; ++i) {
    const double tau = static_cast<double>(steps - i) / steps + kFinalTime;
    const double sigma =
        diffusion_sigma(at::tensor(tau, at::TensorOptions().dtype(at::kDouble))).item<double>();
    const double c = 1e-3 * sigma * sigma / (sigma_final * sigma_final);
    for (int k = 0; k < settings.inner_steps; ++k) update(tau, c, true);
  }
  for (int i = 0; i < settings.final_steps; ++i) {
    for (int k = 0; k < settings.inner_steps; ++k) update(kFinalTime, kFinalStep, false);
  }
  return x;
}

}  // namespace graspecmf::models
