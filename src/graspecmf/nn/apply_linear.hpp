#pragma once
// A torch::nn::Linear applied from const code (its forward() is not const).

#include <torch/nn/functional/linear.h>
#include <torch/nn/modules/linear.h>

namespace graspecmf::nn {

// x W^T + b for the layer's weight W and bias b (none when the layer has no bias).
inline at::Tensor apply_linear(const torch::nn::Linear& layer, const at::Tensor& x) {
  return torch::nn::functional::linear(x, layer->weight, layer->bias);
}

}  // namespace graspecmf::nn
