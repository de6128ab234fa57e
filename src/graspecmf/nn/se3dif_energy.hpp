#pragma once
// SE(3)-DiffusionFields' energy network (Urain et al. 2023; docs/method.md, "Comparison models"):
// a DeepSDF-style feature network evaluated at 30 points fixed to the gripper, and a head from
// their 30 × 7 features to one energy per grasp.

#include <torch/nn/module.h>
#include <torch/nn/modules/linear.h>
#include <torch/nn/modules/normalization.h>
#include <torch/nn/pimpl.h>

#include <cstdint>
#include <vector>

#include "graspecmf/flow/pose_batch.hpp"

namespace graspecmf::nn {

// Linear with weight normalisation: W = g · V / ‖V‖ row by row, g starting at ‖V‖.
class WeightNormLinearImpl : public torch::nn::Module {
 public:
  WeightNormLinearImpl(int64_t in_features, int64_t out_features);
  torch::Tensor forward(const torch::Tensor& x) const;

  torch::Tensor direction, gain, bias;  // V [out, in], g [out], b [out]
};
TORCH_MODULE(WeightNormLinear);

// ψ(x, t, z) → 7 features per query point (channel 0 the distance estimate), with the
// reference's sizes: latent 132, 66 fixed random time frequencies ~ N(0, 30²), eight
// weight-normalised ReLU layers of 512 (the input re-enters at the fifth), dropout 0.2 on the
// latent and after each layer in training, tanh on the output (1 864 341 parameters). Dropout
// masks come from a given CPU generator, so that a seed (and a resumed run) gives the same masks
// on every device.
class Se3DifFeatureNetImpl : public torch::nn::Module {
 public:
  Se3DifFeatureNetImpl();
  // Points x [..., 3], times t [...] and latents z [..., 132] → [..., 7]; dropout in training
  // mode when dropout is given (its masks drawn from it), none otherwise.
  torch::Tensor forward(const torch::Tensor& x, const torch::Tensor& t, const torch::Tensor& z,
                        at::Generator* dropout = nullptr) const;

  torch::Tensor frequencies;  // buffer [66]
  torch::nn::Linear time{nullptr}, position{nullptr};
  std::vector<WeightNormLinear> layers;
  torch::nn::Linear output{nullptr};
};
TORCH_MODULE(Se3DifFeatureNet);

class Se3DifEnergyImpl : public torch::nn::Module {
 public:
  // position_scale: network units per metre, for the gripper points (the reference's are in
  // units of 1/8 m). The 30 points are drawn once from a fixed seed.
  explicit Se3DifEnergyImpl(double position_scale);
  // E [G] of poses x (network units) at times t [G] for latents z [G, 132]; dropout as in
  // Se3DifFeatureNet.
  torch::Tensor forward(const flow::PoseBatch& x, const torch::Tensor& t, const torch::Tensor& z,
                        at::Generator* dropout = nullptr) const;

  torch::Tensor gripper_points;  // buffer [30, 3], network units
  Se3DifFeatureNet features{nullptr};
  torch::nn::Linear hidden{nullptr}, energy{nullptr};
  torch::nn::LayerNorm norm{nullptr};
};
TORCH_MODULE(Se3DifEnergy);

}  // namespace graspecmf::nn
