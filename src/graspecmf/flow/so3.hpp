#pragma once
// Batched SO(3) on tensors (float32 or float64, any leading batch shape [...]): hat/vee, the
// exponential and logarithm maps with Taylor branches at θ → 0 and an axis-from-symmetric-part
// branch near θ = π, and the Lie bracket. Throws Error on a wrong trailing shape or dtype.
// so3_exp and so3_log evaluate float32 input in float64 and round the result (differentiably):
// in float32 arithmetic Rodrigues' formula is only orthonormal to ~1e-6.

#include <ATen/core/Tensor.h>

namespace graspecmf::flow {

// [..., 3] → [..., 3, 3]: the skew matrix [w]× with [w]× v = w × v.
at::Tensor hat(const at::Tensor& w);
// [..., 3, 3] → [..., 3]: the vector of the antisymmetric part of W; vee(hat(w)) = w.
at::Tensor vee(const at::Tensor& W);

// [..., 3] → [..., 3, 3]: Exp(w), the rotation by |w| about w/|w| (Rodrigues). A small non-zero w
// never gives exactly I, and the result is differentiable with finite gradients at w = 0.
at::Tensor so3_exp(const at::Tensor& w);
// [..., 3, 3] → [..., 3]: Log(R) with angle in [0, π], accurate near 0 and near π; at an exact
// half turn it returns π·axis with the correct axis (its sign is arbitrary there). R must be a
// rotation to within rounding of its dtype.
at::Tensor so3_log(const at::Tensor& R);

// [..., 3] × [..., 3] → [..., 3]: the bracket of so(3) in vector form, a × b, which equals
// vee(hat(a) hat(b) − hat(b) hat(a)).
at::Tensor lie_bracket(const at::Tensor& a, const at::Tensor& b);

// [..., 4] unit quaternions (w, x, y, z) → [..., 3, 3] rotation matrices (differentiable; q and −q
// give the same matrix).
at::Tensor quaternion_to_matrix(const at::Tensor& q);

}  // namespace graspecmf::flow
