#include "graspecmf/nn/se3dif_encoder.hpp"

#include <torch/torch.h>

#include "graspecmf/nn/checks.hpp"
#include "graspecmf/nn/gather_rows.hpp"
#include "graspecmf/nn/knn.hpp"

namespace graspecmf::nn {
namespace {

constexpr int64_t kNeighbours = 20;
constexpr int64_t kHidden = 128;
constexpr int64_t kBlocks = 5;
constexpr int64_t kOutVectors = 44;

// The mean over points (dim −3) of v [B, N, C, 3], copied back to every point.
torch::Tensor with_pooled(const torch::Tensor& v) {
  return torch::cat({v, vn_mean_pool(v, -3).unsqueeze(-3).expand_as(v)}, -2);
}

}  // namespace

VNLeakyReLUImpl::VNLeakyReLUImpl(int64_t channels, double slope_value) : slope(slope_value) {
  direction = register_module("direction", VNLinear(channels, channels));
}

torch::Tensor VNLeakyReLUImpl::forward(const torch::Tensor& v) const {
  const auto packed = torch::cat({v, direction->forward(v)}, -2).transpose(-1, -2);
  return vn_leaky_relu_packed(packed.contiguous(), v.size(-2), slope).transpose(-1, -2);
}

VNResnetBlockImpl::VNResnetBlockImpl(int64_t in_channels, int64_t out_channels) {
  act0 = register_module("act0", VNLeakyReLU(in_channels, kDefaultSlope));
  fc0 = register_module("fc0", VNLinear(in_channels, out_channels));
  act1 = register_module("act1", VNLeakyReLU(out_channels, kDefaultSlope));
  fc1 = register_module("fc1", VNLinear(out_channels, out_channels));
  shortcut = register_module("shortcut", VNLinear(in_channels, out_channels));
  torch::NoGradGuard no_grad;
  fc1->weight.zero_();
}

torch::Tensor VNResnetBlockImpl::forward(const torch::Tensor& v) const {
  return shortcut->forward(v) + fc1->forward(act1->forward(fc0->forward(act0->forward(v))));
}

Se3DifEncoderImpl::Se3DifEncoderImpl() {
  edge = register_module("edge", VNLinearLeakyReLU(3, kHidden, false, 0.0));
  lift = register_module("lift", VNLinear(kHidden, 2 * kHidden));
  for (int64_t b = 0; b < kBlocks; ++b) {
    blocks.push_back(
        register_module("block" + std::to_string(b), VNResnetBlock(2 * kHidden, kHidden)));
  }
  out_act = register_module("out_act", VNLeakyReLU(kHidden, 0.0));
  out = register_module("out", VNLinear(kHidden, kOutVectors));
}

torch::Tensor Se3DifEncoderImpl::forward(const torch::Tensor& clouds) const {
  detail::require_shape(clouds, "Se3DifEncoder: clouds", {-1, -1, 3});
  detail::require(clouds.size(1) >= kNeighbours, "Se3DifEncoder: fewer than 20 points");
  // Edges of each point i to its k nearest j (i itself included): [x_j − x_i, x_i, x_j × x_i].
  const auto neighbours = gather_rows(clouds, knn(clouds, kNeighbours));  // [B, N, k, 3]
  const auto centre = clouds.unsqueeze(2).expand_as(neighbours);
  const auto edges =
      torch::stack({neighbours - centre, centre, torch::linalg_cross(neighbours, centre, -1)}, -2);
  auto v = lift->forward(vn_mean_pool(edge->forward(edges), 2));  // [B, N, 256, 3]
  for (int64_t b = 0; b < kBlocks; ++b) {
    v = blocks[static_cast<std::size_t>(b)]->forward(v);
    if (b + 1 < kBlocks) v = with_pooled(v);
  }
  const auto z = out->forward(out_act->forward(vn_mean_pool(v, 1)));  // [B, 44, 3]
  return z.flatten(1);
}

}  // namespace graspecmf::nn
