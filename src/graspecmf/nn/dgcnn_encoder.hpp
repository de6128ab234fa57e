#pragma once
// An ordinary DGCNN encoder on scalar features (Wang et al. 2019), the non-equivariant twin of the
// VN-DGCNN encoder for the ablation of equivariance (docs/method.md, "Comparison models").

#include <torch/nn/module.h>
#include <torch/nn/modules/linear.h>
#include <torch/nn/pimpl.h>

#include <vector>

#include "graspecmf/nn/encoder.hpp"

namespace graspecmf::nn {

class DgcnnEncoderImpl : public torch::nn::Module {
 public:
  // The same options as the VN-DGCNN encoder, but widths and out_channels count scalars. Throws
  // Error on an empty width list or a non-positive width, k or out_channels.
  explicit DgcnnEncoderImpl(EncoderOptions options);

  // points [B, N, 3] float32 (centred and scaled) → z [B, out_channels]. Each EdgeConv layer
  // rebuilds the kNN graph in its input feature space (the point itself included) and averages
  // LeakyReLU(W [h_j − h_i ; h_i] + b) over the neighbours; the layer outputs are concatenated,
  // mapped by a Linear + LeakyReLU head and averaged over the points. Throws Error as Encoder does.
  torch::Tensor forward(const torch::Tensor& points) const;

  const EncoderOptions& options() const { return options_; }

  // Layer l's edge map W [h_j − h_i ; h_i] + b, evaluated per point as A h_j + (C h_i + b): A =
  // W's left half (`neighbour`), C = right half − left half (`centre`, with the bias).
  std::vector<torch::nn::Linear> neighbour, centre;
  torch::nn::Linear head{nullptr};  // Σ widths → out_channels

 private:
  EncoderOptions options_;
};
TORCH_MODULE(DgcnnEncoder);

}  // namespace graspecmf::nn
