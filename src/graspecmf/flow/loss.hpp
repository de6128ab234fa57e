#pragma once
// The flow-matching regression loss and the condition-dropout mask for classifier-free guidance
// (METHOD §5).

#include <ATen/core/Generator.h>
#include <ATen/core/Tensor.h>

#include <cstdint>

namespace graspecmf::flow {

// Mean squared error over the 6 numbers (ω, v) of every grasp, equal weights: a scalar tensor
// (differentiable in the predictions). All four tensors are [B,3], B ≥ 1, with one dtype; Error
// otherwise.
at::Tensor flow_matching_loss(const at::Tensor& omega_pred, const at::Tensor& v_pred,
                              const at::Tensor& omega_target, const at::Tensor& v_target);

// [n] mask of 0/1 in dtype: 1 (keep the condition z) with probability 1 − drop_probability, 0
// (use the null condition) otherwise, independently per grasp, drawn from generator. Throws
// Error for n < 0, drop_probability outside [0, 1], or a dtype other than float32/float64.
at::Tensor cfg_keep_mask(int64_t n, double drop_probability, at::Generator& generator,
                         at::ScalarType dtype = at::kFloat);

}  // namespace graspecmf::flow
