#pragma once
// SE(3)-DiffusionFields' object encoder (Urain et al. 2023; docs/method.md, "Comparison models"): a
// vector-neuron ResNet-PointNet whose first layer sees DGCNN-style edges. Its output vectors rotate
// with the cloud, but the energy network reads their coordinates, so that model is not equivariant.

#include <torch/nn/module.h>
#include <torch/nn/pimpl.h>

#include <cstdint>
#include <vector>

#include "graspecmf/nn/vn_layers.hpp"

namespace graspecmf::nn {

// VN-LeakyReLU whose direction is a learned VN-Linear map of its own input (channels → channels).
class VNLeakyReLUImpl : public torch::nn::Module {
 public:
  VNLeakyReLUImpl(int64_t channels, double slope);
  // [..., C, 3] → [..., C, 3].
  torch::Tensor forward(const torch::Tensor& v) const;

  VNLinear direction{nullptr};
  double slope;
};
TORCH_MODULE(VNLeakyReLU);

// x + f(x) with f = VN-LeakyReLU → VN-Linear(in → out) → VN-LeakyReLU → VN-Linear(out → out,
// zero at the start) and a VN-Linear(in → out) shortcut.
class VNResnetBlockImpl : public torch::nn::Module {
 public:
  VNResnetBlockImpl(int64_t in_channels, int64_t out_channels);
  torch::Tensor forward(const torch::Tensor& v) const;

  VNLeakyReLU act0{nullptr}, act1{nullptr};
  VNLinear fc0{nullptr}, fc1{nullptr}, shortcut{nullptr};
};
TORCH_MODULE(VNResnetBlock);

class Se3DifEncoderImpl : public torch::nn::Module {
 public:
  // The reference's sizes: k = 20 neighbours, 128 hidden vector channels, 5 blocks, 44 output
  // vectors (874 752 parameters).
  Se3DifEncoderImpl();
  // Clouds [B, N, 3] (N ≥ 20) → z [B, 132]: 44 vectors, flattened vector by vector.
  torch::Tensor forward(const torch::Tensor& clouds) const;

  VNLinearLeakyReLU edge{nullptr};  // the edge features' 3 vectors → 128, VN-ReLU
  VNLinear lift{nullptr};           // 128 → 256
  std::vector<VNResnetBlock> blocks;
  VNLeakyReLU out_act{nullptr};  // VN-ReLU on the pooled 128
  VNLinear out{nullptr};         // 128 → 44
};
TORCH_MODULE(Se3DifEncoder);

}  // namespace graspecmf::nn
