#include "graspecmf/models/graspnet_generator.hpp"

#include <ATen/ATen.h>
#include <torch/nn/functional/activation.h>
#include <torch/utils.h>

#include <algorithm>
#include <cmath>

#include "graspecmf/core/error.hpp"
#include "graspecmf/flow/so3.hpp"
#include "graspecmf/models/graspnet_losses.hpp"
#include "graspecmf/nn/checks.hpp"

namespace graspecmf::models {
namespace {

// Grasps decoded at once while sampling: each holds its own copy of the cloud's neighbourhoods
// (about 4 MB for 512 points), so a chunk of 32 stays near 128 MB.
constexpr std::int64_t kDrawChunk = 32;
constexpr std::int64_t kBackboneWidth = 1024;

// Grasps (R, p) [G] as the reference's encoder input: the 4 × 4 matrices, row-major [G, 16].
at::Tensor flattened_matrices(const flow::PoseBatch& grasps) {
  const int64_t g = grasps.R.size(0);
  const auto top = at::cat({grasps.R, grasps.p.unsqueeze(2)}, 2).reshape({g, 12});
  const auto bottom = at::tensor({0.0F, 0.0F, 0.0F, 1.0F}, grasps.R.options()).expand({g, 4});
  return at::cat({top, bottom}, 1);
}

// The reference's per-point features: each point's xyz, then the row of values [B, F] of its
// cloud [B, N, 3] → [B, N, 3 + F].
at::Tensor point_features(const at::Tensor& clouds, const at::Tensor& values) {
  return at::cat(
      {clouds, values.unsqueeze(1).expand({values.size(0), clouds.size(1), values.size(1)})}, 2);
}

}  // namespace

GraspNetGenerator::GraspNetGenerator(Variant variant, const GraspNetOptions& options,
                                     double position_scale)
    : variant_(variant), options_(options), position_scale_(position_scale) {
  if (!(position_scale > 0) || !std::isfinite(position_scale)) {
    throw Error("graspnet: position_scale must be positive and finite");
  }
  const double radius = options.radius * position_scale;
  decoder = register_module("decoder", nn::GraspNetBackbone(nn::GraspNetBackboneOptions{
                                           3 + options.latent_size, radius, options.centroids}));
  rotation = register_module("rotation", torch::nn::Linear(kBackboneWidth, 4));
  translation = register_module("translation", torch::nn::Linear(kBackboneWidth, 3));
  confidence = register_module("confidence", torch::nn::Linear(kBackboneWidth, 1));
  if (variant == Variant::kVae) {
    encoder = register_module("encoder", nn::GraspNetBackbone(nn::GraspNetBackboneOptions{
                                             3 + 16, radius, options.centroids}));
    mu = register_module("mu", torch::nn::Linear(kBackboneWidth, options.latent_size));
    logvar = register_module("logvar", torch::nn::Linear(kBackboneWidth, options.latent_size));
  }
}

Condition GraspNetGenerator::condition(const at::Tensor& clouds) const {
  nn::detail::require_shape(clouds, "graspnet condition: clouds", {-1, -1, 3});
  nn::detail::require(clouds.size(0) > 0, "graspnet condition: no cloud");
  return {{clouds}};
}

GraspNetGenerator::Decoded GraspNetGenerator::decode(const at::Tensor& clouds,
                                                     const at::Tensor& latents) const {
  // LibTorch's forward methods are not const (BatchNorm updates its running statistics in
  // training), so the modules are reached through their shared pointers.
  const auto features = decoder.ptr()->forward(clouds, point_features(clouds, latents));
  const auto q = rotation.ptr()->forward(features);
  const auto unit = q / q.norm(2, {-1}, /*keepdim=*/true).clamp_min(1e-8);
  return {{flow::quaternion_to_matrix(unit), translation.ptr()->forward(features)},
          at::sigmoid(confidence.ptr()->forward(features)).squeeze(-1)};
}

at::Tensor GraspNetGenerator::control_points(const flow::PoseBatch& grasps) const {
  return grasp_control_points(grasps, position_scale_) / position_scale_;
}

std::string GraspNetGenerator::sampler(const SamplingSettings&) const {
  return variant_ == Variant::kVae ? "a decoder pass per grasp, latents from N(0, I)"
                                   : "a decoder pass per grasp, latents from U[0, 1)^" +
                                         std::to_string(options_.latent_size);
}

flow::PoseBatch GraspNetGenerator::draw(const Condition& condition, std::int64_t count,
                                        const SamplingSettings&, at::Generator& generator) const {
  if (count < 0) throw Error("graspnet draw: negative count");
  torch::NoGradGuard no_grad;
  const at::Tensor& clouds = condition.tensors.at(0);
  const int64_t m = clouds.size(0);
  const auto cpu = at::TensorOptions().dtype(at::kFloat);
  const auto latents = variant_ == Variant::kVae
                           ? at::randn({count, options_.latent_size}, generator, cpu)
                           : at::rand({count, options_.latent_size}, generator, cpu);
  std::vector<at::Tensor> rotations, translations;
  for (int64_t start = 0; start < count; start += kDrawChunk) {
    const int64_t n = std::min(kDrawChunk, count - start);
    const auto which = at::arange(start, start + n, at::TensorOptions().dtype(at::kLong)) % m;
    const Decoded decoded = decode(clouds.index_select(0, which.to(clouds.device())),
                                   latents.slice(0, start, start + n).to(clouds.device()));
    rotations.push_back(decoded.grasps.R);
    translations.push_back(decoded.grasps.p);
  }
  if (rotations.empty()) {
    return {at::empty({0, 3, 3}, clouds.options()), at::empty({0, 3}, clouds.options())};
  }
  return {at::cat(rotations), at::cat(translations)};
}

at::Tensor GraspNetGenerator::loss(const TrainingBatch& batch, at::Generator& generator) const {
  flow::check_pose_batch(batch.grasps, "graspnet loss");
  const auto device = batch.points.device();
  const auto clouds = batch.points.index_select(0, batch.object_index);  // [G, N, 3]
  const int64_t g = clouds.size(0), l = options_.latent_size;
  const auto cpu = at::TensorOptions().dtype(at::kFloat);
  const auto truth = control_points(batch.grasps);
  if (variant_ == Variant::kVae) {
    const auto features =
        encoder.ptr()->forward(clouds, point_features(clouds, flattened_matrices(batch.grasps)));
    const auto mean = mu.ptr()->forward(features), log_variance = logvar.ptr()->forward(features);
    const auto noise = at::randn({g, l}, generator, cpu).to(device);
    const Decoded decoded = decode(clouds, mean + (0.5 * log_variance).exp() * noise);
    return vae_loss(control_points(decoded.grasps), truth, decoded.confidence, mean, log_variance,
                    options_.kl_weight, options_.confidence_weight);
  }
  const Decoded decoded = decode(clouds, at::rand({g, l}, generator, cpu).to(device));
  const auto predicted = control_points(decoded.grasps);
  std::vector<at::Tensor> per_object;
  for (int64_t o = 0; o < batch.points.size(0); ++o) {
    const auto mine = (batch.object_index == o).nonzero().squeeze(1);
    if (mine.numel() == 0) continue;
    per_object.push_back(imle_loss(predicted.index_select(0, mine), truth.index_select(0, mine),
                                   decoded.confidence.index_select(0, mine),
                                   options_.confidence_weight));
  }
  if (per_object.empty()) throw Error("graspnet loss: the batch has no grasp");
  return at::stack(per_object).mean();
}

}  // namespace graspecmf::models
