#include "graspecmf/flow/loss.hpp"

#include <ATen/ATen.h>

#include "graspecmf/core/error.hpp"

namespace graspecmf::flow {

at::Tensor flow_matching_loss(const at::Tensor& omega_pred, const at::Tensor& v_pred,
                              const at::Tensor& omega_target, const at::Tensor& v_target) {
  for (const auto* x : {&omega_pred, &v_pred, &omega_target, &v_target}) {
    if (!x->defined() || x->dim() != 2 || x->size(1) != 3 || x->size(0) != omega_pred.size(0) ||
        x->size(0) == 0 || x->scalar_type() != omega_pred.scalar_type()) {
      throw Error(
          "flow_matching_loss: predictions and targets must all be [B,3], B >= 1, of one dtype");
    }
  }
  const auto error = at::cat({omega_pred - omega_target, v_pred - v_target}, -1);  // [B,6]
  return error.square().mean();
}

at::Tensor cfg_keep_mask(int64_t n, double drop_probability, at::Generator& generator,
                         at::ScalarType dtype) {
  if (n < 0) throw Error("cfg_keep_mask: negative size");
  if (!(drop_probability >= 0.0 && drop_probability <= 1.0)) {
    throw Error("cfg_keep_mask: drop probability must be in [0, 1]");
  }
  if (dtype != at::kFloat && dtype != at::kDouble) {
    throw Error("cfg_keep_mask: dtype must be float32 or float64");
  }
  // u ~ U[0, 1): P(u >= p) = 1 − p, so p = 0 keeps everything and p = 1 drops everything.
  const auto u = at::rand({n}, generator, at::TensorOptions().dtype(at::kDouble));
  return (u >= drop_probability).to(dtype);
}

}  // namespace graspecmf::flow
