#pragma once
// 6-DOF GraspNet's generators (`model.type` "graspnet_vae" and "graspnet_gan"; docs/method.md,
// "Comparison models"): a PointNet++ decoder maps a cloud and a latent vector to one grasp and its
// confidence. The VAE trains it with a PointNet++ encoder of the cloud and a true grasp; the "GAN"
// by implicit maximum likelihood (each true grasp pulls the prediction nearest to it).

#include <torch/nn/modules/linear.h>

#include "graspecmf/models/generator.hpp"
#include "graspecmf/nn/graspnet_backbone.hpp"

namespace graspecmf::models {

class GraspNetGenerator : public GeneratorImpl {
 public:
  enum class Variant { kVae, kImle };

  // position_scale: network units per metre (the radius and the loss's control points are
  // converted with it). Throws Error on invalid options.
  GraspNetGenerator(Variant variant, const GraspNetOptions& options, double position_scale);

  // The clouds themselves: the decoder reads a cloud for every grasp it draws.
  Condition condition(const at::Tensor& clouds) const override;
  // Grasp i decodes cloud i mod M with a latent drawn from the prior the reference samples (VAE:
  // N(0, I); GAN: U[0, 1)); the solver settings do not apply. Each cloud is centred on its own
  // centroid, so its grasps are relative to it.
  flow::PoseBatch draw(const Condition& condition, std::int64_t count,
                       const SamplingSettings& settings, at::Generator& generator) const override;
  // VAE: the reparameterised latent of each grasp's encoding, decoded, against the grasp (control
  // points in metres, confidence and KL terms). GAN: one U[0, 1) latent per true grasp, and the
  // IMLE loss of each object's predictions against its grasps, averaged over the objects.
  at::Tensor loss(const TrainingBatch& batch, at::Generator& generator) const override;
  // "a decoder pass per grasp, latents from N(0, I)" (VAE) or "… U[0, 1)^L" (GAN).
  std::string sampler(const SamplingSettings& settings) const override;

  nn::GraspNetBackbone decoder{nullptr};
  nn::GraspNetBackbone encoder{nullptr};  // the VAE's only
  torch::nn::Linear rotation{nullptr}, translation{nullptr}, confidence{nullptr};
  torch::nn::Linear mu{nullptr}, logvar{nullptr};  // the VAE's only

 private:
  struct Decoded {
    flow::PoseBatch grasps;  // network units
    at::Tensor confidence;   // [B]
  };
  // The decoder on clouds [B, N, 3] with latents [B, L].
  Decoded decode(const at::Tensor& clouds, const at::Tensor& latents) const;
  // The control points of grasps in metres [G, 6, 3].
  at::Tensor control_points(const flow::PoseBatch& grasps) const;

  Variant variant_;
  GraspNetOptions options_;
  double position_scale_;
};

}  // namespace graspecmf::models
