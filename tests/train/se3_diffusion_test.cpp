// SE(3)-DiffusionFields' diffusion on energies whose answers are known: the noise scale's values,
// a zero score-matching loss for the exact Gaussian energy, Langevin descending to a minimum, and
// the se3dif generator's distance-field term.

#include "graspecmf/models/se3_diffusion.hpp"

#include <ATen/Parallel.h>
#include <gtest/gtest.h>
#include <torch/torch.h>

#include "graspecmf/core/error.hpp"
#include "graspecmf/flow/prior.hpp"
#include "graspecmf/flow/so3.hpp"
#include "graspecmf/models/se3dif_generator.hpp"

namespace graspecmf::models {
namespace {

class Se3Diffusion : public ::testing::Test {
 protected:
  void SetUp() override { at::set_num_threads(1); }
};

const auto kDouble = torch::TensorOptions().dtype(torch::kDouble);

TEST_F(Se3Diffusion, NoiseScaleRisesFromZeroToItsMaximum) {
  const auto sigma = diffusion_sigma(torch::tensor({1e-5, 0.5, 1.0}, kDouble));
  EXPECT_NEAR(sigma[0].item<double>(), std::sqrt(1e-5), 1e-7);  // σ² ≈ t for small t
  EXPECT_NEAR(sigma[1].item<double>(), std::sqrt(0.5 / (2 * std::log(2.0))), 1e-12);
  EXPECT_NEAR(sigma[2].item<double>(), std::sqrt(0.75 / (2 * std::log(2.0))), 1e-12);  // 0.7355
}

// Grasps near a pose with a small rotation, so that the noisy exponential coordinates stay inside
// the ball of radius π where Log(Exp(φ)) = φ.
flow::PoseBatch grasps(int64_t count) {
  const auto omega = torch::tensor({0.1, -0.2, 0.05}, kDouble).expand({count, 3});
  return {flow::so3_exp(omega), torch::tensor({0.3, 0.0, -0.1}, kDouble).expand({count, 3})};
}

// a · |φ(H) − φ₀|² / (2σ(t)²), φ = (p, Log R): for a = 1 the exact log-density of the noise.
PoseEnergy gaussian_energy(const flow::PoseBatch& centre, const at::Tensor& a) {
  const auto phi0 = torch::cat({centre.p, flow::so3_log(centre.R)}, 1);
  return [phi0, a](const flow::PoseBatch& h, const at::Tensor& t) {
    const auto phi = torch::cat({h.p, flow::so3_log(h.R)}, 1);
    const auto sigma = diffusion_sigma(t);
    return a * (phi - phi0).pow(2).sum(1) / (2 * sigma * sigma);
  };
}

// The exact energy's gradient is the target n/σ, so its loss vanishes; twice that energy misses by
// the target itself; and the loss is differentiable in the energy's parameter.
TEST_F(Se3Diffusion, TheExactGaussianEnergyHasZeroLoss) {
  const flow::PoseBatch x = grasps(32);
  at::Generator a = flow::make_generator(3), b = flow::make_generator(3);
  const auto one = torch::ones({}, kDouble);
  {
    torch::NoGradGuard no_grad;  // as for a validation loss: the loss still takes its gradient
    EXPECT_LT(denoising_score_matching_loss(gaussian_energy(x, one), x, a).item<double>(), 1e-8);
  }
  const auto two = torch::full({}, 2.0, kDouble).requires_grad_(true);
  const auto loss = denoising_score_matching_loss(gaussian_energy(x, two), x, b);
  EXPECT_GT(loss.item<double>(), 0.01);
  loss.backward();
  EXPECT_GT(two.grad().item<double>(), 0.0);  // less weight would lower it
}

// E = |p − p₀|²/(2s²) + |Log(R₀ᵀ R)|²/(2s²) has its minimum at (R₀, p₀); the noise-free final steps
// (step 0.003) descend to it from prior samples, and a seed gives the same run.
TEST_F(Se3Diffusion, LangevinDescendsToTheMinimumAndIsSeeded) {
  const flow::PoseBatch centre = grasps(1);
  const PoseEnergy energy = [&](const flow::PoseBatch& h, const at::Tensor&) {
    const auto rotation = flow::so3_log(centre.R.transpose(1, 2).matmul(h.R));
    return ((h.p - centre.p).pow(2).sum(1) + rotation.pow(2).sum(1)) / (2 * 0.05 * 0.05);
  };
  at::Generator prior = flow::make_generator(1);
  flow::PoseBatch x0 = flow::sample_prior(16, 0.1, prior, torch::kDouble);
  x0.R = flow::so3_exp(0.3 * flow::so3_log(x0.R));  // within the energy's basin
  LangevinSettings descend;
  descend.annealed_steps = 0;
  at::Generator g = flow::make_generator(2);
  const flow::PoseBatch x = annealed_langevin(energy, x0, descend, g);
  EXPECT_LT((x.p - centre.p).abs().max().item<double>(), 1e-6);
  EXPECT_LT((x.R - centre.R).abs().max().item<double>(), 1e-6);

  LangevinSettings noisy;
  noisy.annealed_steps = 5;
  noisy.final_steps = 0;
  at::Generator a = flow::make_generator(7), b = flow::make_generator(7);
  const flow::PoseBatch ya = annealed_langevin(energy, x0, noisy, a);
  const flow::PoseBatch yb = annealed_langevin(energy, x0, noisy, b);
  EXPECT_TRUE(torch::equal(ya.R, yb.R));
  EXPECT_TRUE(torch::equal(ya.p, yb.p));
  const auto eye = torch::eye(3, kDouble).expand({16, 3, 3});
  EXPECT_LT((ya.R.transpose(1, 2).matmul(ya.R) - eye).abs().max().item<double>(), 1e-12);
  noisy.inner_steps = -1;
  EXPECT_THROW(annealed_langevin(energy, x0, noisy, a), Error);
}

}  // namespace
}  // namespace graspecmf::models

namespace graspecmf::models {
namespace {

// The se3dif generator's loss is the score-matching loss plus the mean |clip(ψ₀) − clip(d)| over
// the distance queries, clipped at 7.5 cm (0.6 at × 8), at times drawn after the score-matching
// draws. Checked in eval mode, where dropout draws nothing.
TEST_F(Se3Diffusion, TheGeneratorAddsTheClippedDistanceLoss) {
  torch::manual_seed(2);
  Se3DifGenerator model(8.0, 1.0);
  model.eval();
  at::Generator make = flow::make_generator(4);
  TrainingBatch batch;
  batch.points = at::randn({2, 64, 3}, make);
  batch.object_index = torch::tensor({0, 0, 1}, torch::kLong);
  batch.grasps = flow::sample_prior(3, 1.0, make);
  const TrainingBatch without = batch;
  batch.distance_points = at::randn({2, 5, 3}, make);
  batch.distances = torch::tensor({{0.0, 0.1, 0.59, 0.61, 5.0}, {0.2, 0.3, 0.0, 2.0, 0.05}});
  at::Generator a = flow::make_generator(7), b = flow::make_generator(7);
  const double with_distances = model.loss(batch, a).item<double>();
  const double score_matching = model.loss(without, b).item<double>();
  // b now stands where the distance term's draws begin.
  const auto times = at::rand({2, 5}, b);
  const auto z = model.encoder->forward(batch.points);
  const auto predicted =
      model.energy->features
          ->forward(batch.distance_points, times, z.unsqueeze(1).expand({2, 5, z.size(1)}))
          .select(-1, 0);
  const double expected =
      (predicted.clamp_max(0.6) - batch.distances.clamp_max(0.6)).abs().mean().item<double>();
  EXPECT_GT(expected, 0.0);
  EXPECT_NEAR(with_distances - score_matching, expected, 1e-6);
}

}  // namespace
}  // namespace graspecmf::models
