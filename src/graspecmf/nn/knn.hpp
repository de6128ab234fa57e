#pragma once
// k nearest neighbours in feature space for dynamic graph convolutions (docs/method.md, "Encoder").

#include <ATen/core/Tensor.h>

#include <cstdint>

namespace graspecmf::nn {

// For features [B, N, D] (float32), the indices [B, N, k] (int64) of each row's k nearest rows
// of the same batch entry by Euclidean distance: the row itself first, then the other k − 1 in
// a deterministic order; of equally distant rows the lower index is taken. One GEMM for the
// distances and a selection per row (no full sort); no gradient. Throws Error on a wrong shape,
// k outside [1, N] or a non-finite feature.
// CPU tensors take that selection; others (CUDA) knn_any_device.
at::Tensor knn(const at::Tensor& features, int64_t k);

// The same neighbours on any device by the same distances and at::topk; equally distant rows come
// in topk's order, not by index. Unchecked.
at::Tensor knn_any_device(const at::Tensor& features, int64_t k);

}  // namespace graspecmf::nn
