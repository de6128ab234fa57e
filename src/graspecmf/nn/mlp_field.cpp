#include "graspecmf/nn/mlp_field.hpp"

#include <torch/torch.h>

#include <string>
#include <utility>

#include "graspecmf/nn/apply_linear.hpp"
#include "graspecmf/nn/checks.hpp"

namespace graspecmf::nn {

MlpFieldImpl::MlpFieldImpl(VectorFieldOptions options) : options_(std::move(options)) {
  const std::vector<int64_t>& widths = options_.hidden_widths;
  detail::require(!widths.empty(), "MlpField: hidden_widths must not be empty");
  detail::require(options_.z_channels >= 1, "MlpField: z_channels must be positive");
  detail::require(!options_.z_every_layer, "MlpField: z_every_layer is not supported");
  for (const int64_t w : widths) detail::require(w >= 1, "MlpField: widths must be positive");
  pose = register_module("pose",
                         torch::nn::Linear(torch::nn::LinearOptions(13, widths[0]).bias(false)));
  z = register_module("z", torch::nn::Linear(options_.z_channels, widths[0]));
  for (std::size_t l = 1; l < widths.size(); ++l) {
    hidden.push_back(
        register_module("hidden" + std::to_string(l), torch::nn::Linear(widths[l - 1], widths[l])));
  }
  out = register_module("out", torch::nn::Linear(widths.back(), 6));
}

torch::Tensor MlpFieldImpl::condition(const torch::Tensor& object_z) const {
  detail::require_shape(object_z, "MlpField: z", {-1, options_.z_channels});
  return torch::nn::functional::linear(object_z, z->weight);
}

std::pair<torch::Tensor, torch::Tensor> MlpFieldImpl::forward(const torch::Tensor& condition,
                                                              const torch::Tensor& object_index,
                                                              const torch::Tensor& rotation,
                                                              const torch::Tensor& position,
                                                              const torch::Tensor& time,
                                                              const torch::Tensor& keep) const {
  const int64_t g = rotation.size(0);
  detail::require_shape(rotation, "MlpField: rotation", {g, 3, 3});
  detail::require_shape(position, "MlpField: position", {g, 3});
  const torch::Tensor inputs =
      torch::cat({rotation.reshape({g, 9}), position, time.reshape({g, 1})}, 1);
  // W_z (keep · z) + b: the null condition keeps only the bias.
  const torch::Tensor z_part =
      condition.index_select(0, object_index) * keep.unsqueeze(1) + z->bias;
  torch::Tensor h = torch::leaky_relu(apply_linear(pose, inputs) + z_part, options_.slope);
  for (const torch::nn::Linear& layer : hidden) {
    h = torch::leaky_relu(apply_linear(layer, h), options_.slope);
  }
  const torch::Tensor velocity = apply_linear(out, h);
  return {velocity.narrow(1, 0, 3), velocity.narrow(1, 3, 3)};
}

}  // namespace graspecmf::nn
