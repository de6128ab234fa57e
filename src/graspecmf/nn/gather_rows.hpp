#pragma once
// Batched row lookup shared by the point-cloud layers (neighbour features, group members).

#include <ATen/core/Tensor.h>

namespace graspecmf::nn {

// The rows of values [B, N, ...] picked per batch entry by index [B, ...] (int64, entries in
// [0, N), unchecked) → [B, index dims..., value dims...]; differentiable in values.
at::Tensor gather_rows(const at::Tensor& values, const at::Tensor& index);

}  // namespace graspecmf::nn
