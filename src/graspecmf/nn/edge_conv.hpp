#pragma once
// The fused neighbour aggregation of a VN EdgeConv layer (docs/method.md, "Encoder"), channels
// last.

#include <ATen/core/Tensor.h>

namespace graspecmf::nn {

// With per_point [B, N, 3, 4C] holding, along the last axis, A_f·V, B_f·V, A_d·V and B_d·V
// (C channels each, the vector axis before them) and index [B, N, k] (int64, from knn), returns
// out [B, N, 3, C], out_i = 1/k Σ_{j ∈ index_i} VN-LeakyReLU(A_f V_j + B_f V_i, A_d V_j + B_d
// V_i). No per-edge tensor is stored. Differentiable in per_point (first order only).
// CPU tensors take the fused kernel; others (CUDA) edge_mean_leaky_relu_any_device.
at::Tensor edge_mean_leaky_relu(const at::Tensor& per_point, const at::Tensor& index, double slope);

// The same in tensor operations on any device: gathers the [B, N, k, 3, 2C] edge features, so
// it stores per-edge tensors; autograd differentiates it. Unchecked.
at::Tensor edge_mean_leaky_relu_any_device(const at::Tensor& per_point, const at::Tensor& index,
                                           double slope);

}  // namespace graspecmf::nn
