#include "graspecmf/nn/dgcnn_encoder.hpp"

#include <torch/torch.h>

#include <numeric>
#include <string>
#include <utility>

#include "graspecmf/nn/apply_linear.hpp"
#include "graspecmf/nn/checks.hpp"
#include "graspecmf/nn/gather_rows.hpp"
#include "graspecmf/nn/knn.hpp"

namespace graspecmf::nn {

DgcnnEncoderImpl::DgcnnEncoderImpl(EncoderOptions options) : options_(std::move(options)) {
  detail::require(!options_.widths.empty(), "DgcnnEncoder: widths must not be empty");
  detail::require(options_.k >= 1 && options_.out_channels >= 1,
                  "DgcnnEncoder: k and out_channels must be positive");
  int64_t in = 3;
  for (std::size_t l = 0; l < options_.widths.size(); ++l) {
    const int64_t width = options_.widths[l];
    detail::require(width >= 1, "DgcnnEncoder: widths must be positive");
    const std::string name = std::to_string(l);
    neighbour.push_back(register_module(
        "neighbour" + name, torch::nn::Linear(torch::nn::LinearOptions(in, width).bias(false))));
    centre.push_back(register_module("centre" + name, torch::nn::Linear(in, width)));
    in = width;
  }
  const int64_t concatenated =
      std::accumulate(options_.widths.begin(), options_.widths.end(), int64_t{0});
  head = register_module("head", torch::nn::Linear(concatenated, options_.out_channels));
}

torch::Tensor DgcnnEncoderImpl::forward(const torch::Tensor& points) const {
  detail::require_clouds(points, "DgcnnEncoder", options_.k);
  const int64_t k = options_.k;
  torch::Tensor h = points;
  std::vector<torch::Tensor> outputs;
  for (std::size_t l = 0; l < neighbour.size(); ++l) {
    const torch::Tensor index = knn(h.detach().contiguous(), k);
    const torch::Tensor edges =
        gather_rows(apply_linear(neighbour[l], h), index) + apply_linear(centre[l], h).unsqueeze(2);
    h = torch::leaky_relu(edges, options_.slope).mean(2);
    outputs.push_back(h);
  }
  const torch::Tensor per_point =
      torch::leaky_relu(apply_linear(head, torch::cat(outputs, -1)), options_.slope);
  return per_point.mean(1);
}

}  // namespace graspecmf::nn
