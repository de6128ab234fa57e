#include "graspecmf/nn/encoder.hpp"

#include <numeric>
#include <string>
#include <utility>

#include "graspecmf/nn/checks.hpp"
#include "graspecmf/nn/edge_conv.hpp"
#include "graspecmf/nn/knn.hpp"

namespace graspecmf::nn {

namespace {

// The four per-point maps of an EdgeConv layer stacked as [A_f; B_f; A_d; B_d] ([4C, C_in]).
torch::Tensor per_point_weights(const VNLinearLeakyReLUImpl& layer) {
  const int64_t in = layer.feature->weight.size(1) / 2;
  const auto split = [in](const torch::Tensor& w) {
    const auto left = w.narrow(1, 0, in);
    return std::pair{left, w.narrow(1, in, in) - left};
  };
  const auto [a_f, b_f] = split(layer.feature->weight);
  const auto [a_d, b_d] = split(layer.direction->weight);
  return torch::cat({a_f, b_f, a_d, b_d});
}

}  // namespace

EncoderImpl::EncoderImpl(EncoderOptions options) : options_(std::move(options)) {
  detail::require(!options_.widths.empty(), "Encoder: widths must not be empty");
  detail::require(options_.k >= 1 && options_.out_channels >= 1,
                  "Encoder: k and out_channels must be positive");
  int64_t in = 1;
  for (std::size_t l = 0; l < options_.widths.size(); ++l) {
    const int64_t width = options_.widths[l];
    detail::require(width >= 1, "Encoder: widths must be positive");
    edge_layers.push_back(register_module("edge" + std::to_string(l),
                                          VNLinearLeakyReLU(2 * in, width, false, options_.slope)));
    in = width;
  }
  const int64_t concatenated =
      std::accumulate(options_.widths.begin(), options_.widths.end(), int64_t{0});
  head = register_module(
      "head", VNLinearLeakyReLU(concatenated, options_.out_channels, true, options_.slope));
}

torch::Tensor EncoderImpl::forward(const torch::Tensor& points) const {
  detail::require_clouds(points, "Encoder", options_.k);
  const int64_t batch = points.size(0);
  const int64_t n = points.size(1);

  // Features stay channels last, [B, N, 3, C], so every map is one GEMM over B·N·3 rows.
  auto v = points.unsqueeze(-1);
  std::vector<torch::Tensor> outputs;
  outputs.reserve(edge_layers.size());
  for (const auto& layer : edge_layers) {
    const auto index = knn(v.reshape({batch, n, -1}), options_.k);
    v = edge_mean_leaky_relu(torch::linear(v, per_point_weights(*layer)), index, layer->slope);
    outputs.push_back(v);
  }
  const auto per_point = head->forward(torch::cat(outputs, -1).transpose(-1, -2));
  return vn_mean_pool(per_point, 1).contiguous();
}

}  // namespace graspecmf::nn
