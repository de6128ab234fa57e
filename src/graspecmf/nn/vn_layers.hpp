#pragma once
// Vector-neuron (VN) layers (docs/method.md, "Vector-neuron layers"). A VN feature is a float32
// tensor [..., C, 3]: C vector channels, a rotation acts on the last axis. Every map here commutes
// with rotations. Weights start uniform in ±1/sqrt(in_channels) (the bound of PyTorch's nn.Linear
// default).

#include <torch/nn/module.h>
#include <torch/nn/pimpl.h>

#include <cstdint>

namespace graspecmf::nn {

// Negative slope α of VN-LeakyReLU used throughout (the reference's 0.2).
inline constexpr double kDefaultSlope = 0.2;

// V' = W V over channels, no bias: [..., in, 3] → [..., out, 3]. Throws Error on a wrong shape.
class VNLinearImpl : public torch::nn::Module {
 public:
  VNLinearImpl(int64_t in_channels, int64_t out_channels);
  torch::Tensor forward(const torch::Tensor& v) const;

  torch::Tensor weight;  // [out, in]
};
TORCH_MODULE(VNLinear);

// VN-LeakyReLU, channels last: packed [..., 3, C + D] holds the features q in its first C
// columns and their directions d in the last D (= C, or 1 shared by all channels); returns
// [..., 3, C], q − (1−slope)·min(⟨q,d⟩,0)/(‖d‖²+1e-6)·d. One fused pass forward and backward
// (first-order gradients). Throws Error unless packed is float32 [..., 3, C + C or C + 1].
// CPU tensors take a hand-written kernel; others (CUDA) vn_leaky_relu_packed_any_device.
torch::Tensor vn_leaky_relu_packed(const torch::Tensor& packed, int64_t channels, double slope);

// The same map in tensor operations on any device (autograd differentiates it); unchecked.
torch::Tensor vn_leaky_relu_packed_any_device(const torch::Tensor& packed, int64_t channels,
                                              double slope);

// Mean of a VN feature over a non-vector axis `dim` (neighbours, points): equivariant pooling.
torch::Tensor vn_mean_pool(const torch::Tensor& v, int64_t dim);

// VN-Linear + VN-LeakyReLU: q = W_f V and d = W_d V both from the input V, then VN-LeakyReLU.
// [..., in, 3] → [..., out, 3]; d has `out` channels, or one when `shared_direction`.
class VNLinearLeakyReLUImpl : public torch::nn::Module {
 public:
  VNLinearLeakyReLUImpl(int64_t in_channels, int64_t out_channels, bool shared_direction = false,
                        double slope = kDefaultSlope);
  torch::Tensor forward(const torch::Tensor& v) const;
  // Channels last: x [..., 3, m] holds the first m ≤ in input channels; `extra` (or undefined) is
  // the other channels' pre-activation term [..., 3, out + D]. Returns [..., 3, out].
  torch::Tensor forward_channels_last(const torch::Tensor& x,
                                      const torch::Tensor& extra = {}) const;
  // [out + D, count]: W_f's then W_d's columns for the input channels [first, first + count).
  torch::Tensor packed_weight(int64_t first, int64_t count) const;

  VNLinear feature{nullptr};    // W_f: in → out
  VNLinear direction{nullptr};  // W_d: in → out, or in → 1 when shared
  double slope;
};
TORCH_MODULE(VNLinearLeakyReLU);

}  // namespace graspecmf::nn
