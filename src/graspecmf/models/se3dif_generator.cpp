#include "graspecmf/models/se3dif_generator.hpp"

#include <ATen/ATen.h>
#include <torch/utils.h>

#include <cmath>

#include "graspecmf/core/error.hpp"
#include "graspecmf/flow/prior.hpp"

namespace graspecmf::models {
namespace {

constexpr double kDistanceClip = 0.075;  // metres

}  // namespace

Se3DifGenerator::Se3DifGenerator(double position_scale, double prior_position_std)
    : prior_position_std_(prior_position_std), distance_clip_(kDistanceClip * position_scale) {
  if (!(position_scale > 0) || !std::isfinite(position_scale)) {
    throw Error("se3dif: position_scale must be positive and finite");
  }
  encoder = register_module("encoder", nn::Se3DifEncoder());
  energy = register_module("energy", nn::Se3DifEnergy(position_scale));
}

PoseEnergy Se3DifGenerator::energy_with(const at::Tensor& z, at::Generator* dropout) const {
  return [this, z, dropout](const flow::PoseBatch& x, const at::Tensor& t) {
    return energy->forward(x, t, z, dropout);
  };
}

Condition Se3DifGenerator::condition(const at::Tensor& clouds) const {
  return {{encoder->forward(clouds).mean(0, /*keepdim=*/true)}};
}

std::string Se3DifGenerator::sampler(const SamplingSettings&) const {
  const LangevinSettings s;
  return "annealed Langevin, " + std::to_string(s.annealed_steps) + " + " +
         std::to_string(s.final_steps) + " levels × " + std::to_string(s.inner_steps) + " updates";
}

flow::PoseBatch Se3DifGenerator::draw(const Condition& condition, std::int64_t count,
                                      const SamplingSettings&, at::Generator& generator) const {
  if (count < 0) throw Error("se3dif draw: negative count");
  const at::Tensor& z = condition.tensors.at(0);
  flow::PoseBatch x0 = flow::sample_prior(count, prior_position_std_, generator);
  x0 = {x0.R.to(z.device()), x0.p.to(z.device())};
  const flow::PoseBatch x = annealed_langevin(energy_with(z.expand({count, z.size(1)}), nullptr),
                                              x0, LangevinSettings{}, generator);
  return {x.R.detach(), x.p.detach()};
}

at::Tensor Se3DifGenerator::loss(const TrainingBatch& batch, at::Generator& generator) const {
  const at::Tensor latents = encoder->forward(batch.points);
  const at::Tensor z = latents.index_select(0, batch.object_index);
  at::Tensor loss =
      denoising_score_matching_loss(energy_with(z, &generator), batch.grasps, generator);
  if (!batch.distances.defined()) return loss;
  const at::Tensor times = at::rand(batch.distances.sizes(), generator).to(latents.device());
  const at::Tensor predicted =
      energy->features
          ->forward(batch.distance_points, times,
                    latents.unsqueeze(1).expand({-1, batch.distances.size(1), -1}), &generator)
          .select(-1, 0);
  const auto clip = [this](const at::Tensor& d) { return d.clamp(-10.0, distance_clip_); };
  return loss + (clip(predicted) - clip(batch.distances)).abs().mean();
}

}  // namespace graspecmf::models
