#pragma once
// SE(3)-DiffusionFields as a generator (`model.type` "se3dif"; docs/method.md, "Comparison
// models"): an energy over grasp poses conditioned on the object's latent, trained by projected
// denoising score matching plus a distance-field loss on its feature network, and sampled by
// annealed Langevin dynamics from the flow's prior.

#include "graspecmf/models/generator.hpp"
#include "graspecmf/models/se3_diffusion.hpp"
#include "graspecmf/nn/se3dif_encoder.hpp"
#include "graspecmf/nn/se3dif_energy.hpp"

namespace graspecmf::models {

class Se3DifGenerator : public GeneratorImpl {
 public:
  // position_scale: network units per metre; prior_position_std: the starting poses' position
  // spread in network units (the reference's 1 at ×8). Throws Error on invalid values.
  Se3DifGenerator(double position_scale, double prior_position_std);

  // The mean of the M clouds' latents [1, 132].
  Condition condition(const at::Tensor& clouds) const override;
  // Langevin from Haar × Gaussian starting poses (the solver settings do not apply).
  flow::PoseBatch draw(const Condition& condition, std::int64_t count,
                       const SamplingSettings& settings, at::Generator& generator) const override;
  // The denoising-score-matching loss of the batch's grasps, each under its object's latent, plus,
  // when the batch has distance targets, the mean |clip(ψ₀(q, k, z)) − clip(d)| over its queries,
  // k ~ U[0, 1] per query, both clipped to at most 7.5 cm (the reference's 0.6 at × 8).
  at::Tensor loss(const TrainingBatch& batch, at::Generator& generator) const override;
  // "annealed Langevin, 70 + 50 levels × 2 updates".
  std::string sampler(const SamplingSettings& settings) const override;

  nn::Se3DifEncoder encoder{nullptr};
  nn::Se3DifEnergy energy{nullptr};

 private:
  // The energy of poses under latents z [G, 132], with dropout masks from `dropout` (or none).
  PoseEnergy energy_with(const at::Tensor& z, at::Generator* dropout) const;

  double prior_position_std_;
  double distance_clip_;  // network units
};

}  // namespace graspecmf::models
