#pragma once
// An ordinary MLP vector field on SO(3) × R³, the non-equivariant twin of VectorField for the
// ablation of equivariance (docs/method.md, "Comparison models").

#include <torch/nn/module.h>
#include <torch/nn/modules/linear.h>
#include <torch/nn/pimpl.h>

#include <utility>
#include <vector>

#include "graspecmf/nn/vector_field.hpp"

namespace graspecmf::nn {

class MlpFieldImpl : public torch::nn::Module {
 public:
  // z_channels scalars of z, hidden_widths scalar layers (Linear + LeakyReLU with `slope`).
  // Throws Error on an empty width list, a non-positive width or z_channels, or z_every_layer.
  explicit MlpFieldImpl(VectorFieldOptions options);

  // The first layer's z part without its bias, W_z z, for z [O, z_channels]: computed once per
  // object.
  torch::Tensor condition(const torch::Tensor& z) const;

  // (ω, v), each [G, 3], for grasps R [G, 3, 3], p [G, 3] at times t [G] of the objects
  // object_index [G] of `condition` [O, hidden_widths[0]]; keep [G] is 1 where a grasp sees its
  // object and 0 for the null condition (z = 0). The input is [R row-major ; p ; t ; z].
  std::pair<torch::Tensor, torch::Tensor> forward(const torch::Tensor& condition,
                                                  const torch::Tensor& object_index,
                                                  const torch::Tensor& rotation,
                                                  const torch::Tensor& position,
                                                  const torch::Tensor& time,
                                                  const torch::Tensor& keep) const;

  const VectorFieldOptions& options() const { return options_; }

  torch::nn::Linear pose{nullptr};        // [R ; p ; t] (13) → hidden_widths[0], no bias
  torch::nn::Linear z{nullptr};           // z → hidden_widths[0], holding the first layer's bias
  std::vector<torch::nn::Linear> hidden;  // hidden_widths[l − 1] → hidden_widths[l]
  torch::nn::Linear out{nullptr};         // last width → 6: (ω, v)

 private:
  VectorFieldOptions options_;
};
TORCH_MODULE(MlpField);

}  // namespace graspecmf::nn
