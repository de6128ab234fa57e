#pragma once
// The VN-DGCNN encoder (docs/method.md, "Encoder"): a centred, scaled point cloud → z, a list of
// vectors that rotates with the cloud, E(g·P) = g·E(P).

#include <torch/nn/module.h>
#include <torch/nn/pimpl.h>

#include <cstdint>
#include <vector>

#include "graspecmf/nn/vn_layers.hpp"

namespace graspecmf::nn {

struct EncoderOptions {
  std::vector<int64_t> widths{21, 21, 42, 85, 170};  // output channels of the EdgeConv layers
  int64_t k = 40;                // neighbours per point in every kNN graph, the point included
  int64_t out_channels = 341;    // vectors in z
  int64_t points = 1024;         // points callers sample per cloud; any N ≥ k is accepted
  double slope = kDefaultSlope;  // VN-LeakyReLU negative slope
};

class EncoderImpl : public torch::nn::Module {
 public:
  // Throws Error on an empty width list or a non-positive width, k or out_channels.
  explicit EncoderImpl(EncoderOptions options = {});

  // points [B, N, 3] float32 (centred and scaled) → z [B, out_channels, 3]. Each EdgeConv layer
  // rebuilds the kNN graph in its input feature space; all layer outputs are concatenated, mapped
  // by `head` and averaged over the points. Throws Error on a wrong shape or dtype, an empty batch
  // or cloud, N < k, or a non-finite coordinate.
  torch::Tensor forward(const torch::Tensor& points) const;

  const EncoderOptions& options() const { return options_; }

  // Layer l maps the edge feature [V_j − V_i ; V_i] (2·C_in channels) to widths[l] channels; it
  // is evaluated per point (A = W_left, B = W_right − W_left) and fused per edge, never per edge.
  std::vector<VNLinearLeakyReLU> edge_layers;
  VNLinearLeakyReLU head{nullptr};  // Σ widths → out_channels, one shared direction

 private:
  EncoderOptions options_;
};
TORCH_MODULE(Encoder);

}  // namespace graspecmf::nn
