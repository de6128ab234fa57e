#include "graspecmf/flow/so3.hpp"

#include <ATen/ATen.h>

#include <string>

#include "graspecmf/core/error.hpp"

namespace graspecmf::flow {

namespace {

// Below this angle the Taylor series are used; their first omitted terms are O(θ⁶) ≈ 1e-24.
constexpr double kSmallAngle = 1e-4;
// so3_log recovers the axis from the symmetric part when cos θ < this (θ > ~2.69 rad), where the
// antisymmetric part sin θ · axis has lost relative accuracy (as in lie::so3_log).
constexpr double kNearPiCos = -0.9;

void check_float(const at::Tensor& x, const char* where) {
  if (!x.defined() || (x.scalar_type() != at::kFloat && x.scalar_type() != at::kDouble)) {
    throw Error(std::string(where) + ": expected a float32 or float64 tensor");
  }
}

void check_vectors(const at::Tensor& w, const char* where) {
  check_float(w, where);
  if (w.dim() < 1 || w.size(-1) != 3) {
    throw Error(std::string(where) + ": expected a tensor of shape [..., 3]");
  }
}

void check_matrices(const at::Tensor& W, const char* where) {
  check_float(W, where);
  if (W.dim() < 2 || W.size(-1) != 3 || W.size(-2) != 3) {
    throw Error(std::string(where) + ": expected a tensor of shape [..., 3, 3]");
  }
}

// Entry (i, j) of a batch of matrices, shape [...].
at::Tensor entry(const at::Tensor& M, int64_t i, int64_t j) {
  return M.select(-2, i).select(-1, j);
}

}  // namespace

at::Tensor hat(const at::Tensor& w) {
  check_vectors(w, "hat");
  const auto x = w.select(-1, 0);
  const auto y = w.select(-1, 1);
  const auto z = w.select(-1, 2);
  const auto o = at::zeros_like(x);
  const auto row0 = at::stack({o, -z, y}, -1);
  const auto row1 = at::stack({z, o, -x}, -1);
  const auto row2 = at::stack({-y, x, o}, -1);
  return at::stack({row0, row1, row2}, -2);
}

at::Tensor vee(const at::Tensor& W) {
  check_matrices(W, "vee");
  return 0.5 * at::stack({entry(W, 2, 1) - entry(W, 1, 2), entry(W, 0, 2) - entry(W, 2, 0),
                          entry(W, 1, 0) - entry(W, 0, 1)},
                         -1);
}

at::Tensor so3_exp(const at::Tensor& w) {
  check_vectors(w, "so3_exp");
  if (w.scalar_type() == at::kFloat) return so3_exp(w.to(at::kDouble)).to(at::kFloat);
  const auto theta2 = (w * w).sum(-1, /*keepdim=*/true).unsqueeze(-1);  // [..., 1, 1]
  const auto small = theta2 < kSmallAngle * kSmallAngle;
  // The closed forms see θ = 1 where the series is used, so neither branch makes inf or NaN
  // (which would poison the gradient through at::where).
  const auto theta = at::where(small, at::ones_like(theta2), theta2).sqrt();
  const auto theta4 = theta2 * theta2;
  const auto half_sinc = (0.5 * theta).sin() / (0.5 * theta);
  const auto a = at::where(small, 1.0 - theta2 / 6.0 + theta4 / 120.0, theta.sin() / theta);
  // b = (1 − cos θ)/θ² = ½ (sin(θ/2) / (θ/2))², free of cancellation.
  const auto b =
      at::where(small, 0.5 - theta2 / 24.0 + theta4 / 720.0, 0.5 * half_sinc * half_sinc);
  // Exp(w) = I + a [w]× + b [w]ײ with [w]ײ = w wᵀ − θ² I.
  const auto eye = at::eye(3, w.options());
  const auto outer = w.unsqueeze(-1) * w.unsqueeze(-2);
  return (1.0 - b * theta2) * eye + a * hat(w) + b * outer;
}

at::Tensor so3_log(const at::Tensor& R) {
  check_matrices(R, "so3_log");
  if (R.scalar_type() == at::kFloat) return so3_log(R.to(at::kDouble)).to(at::kFloat);
  const auto v = vee(R);  // sin θ · axis
  const auto sin_theta = v.norm(2, {-1}, /*keepdim=*/true);
  const auto cos_theta = 0.5 * (R.diagonal(0, -2, -1).sum(-1, /*keepdim=*/true) - 1.0);
  const auto theta = at::atan2(sin_theta, cos_theta);

  // Generic branch: θ / sin θ · v, with its Taylor series for small θ.
  const auto near_pi = cos_theta < kNearPiCos;
  const auto small = theta < kSmallAngle;
  const auto t2 = theta * theta;
  const auto safe_sin = at::where(small.logical_or(near_pi), at::ones_like(sin_theta), sin_theta);
  const auto scale = at::where(small, 1.0 + t2 / 6.0 + 7.0 / 360.0 * t2 * t2, theta / safe_sin);

  // Near π: (R + Rᵀ)/2 − cos θ I = (1 − cos θ) a aᵀ; its column with the largest diagonal entry is
  // the best-conditioned multiple of the axis a, whose sign is taken from v.
  const auto eye = at::eye(3, R.options());
  const auto B = 0.5 * (R + R.transpose(-1, -2)) - cos_theta.unsqueeze(-1) * eye;
  const auto k = B.diagonal(0, -2, -1).argmax(-1, /*keepdim=*/true);  // [..., 1]
  const auto column = B.gather(-1, k.unsqueeze(-1).expand_as(B.narrow(-1, 0, 1))).squeeze(-1);
  const auto column_norm = column.norm(2, {-1}, /*keepdim=*/true);
  const auto axis = column / at::where(near_pi, column_norm, at::ones_like(column_norm));
  const auto flip = (axis * v).sum(-1, /*keepdim=*/true) < 0.0;
  const auto signed_axis = at::where(flip, -axis, axis);

  return at::where(near_pi, theta * signed_axis, scale * v);
}

at::Tensor lie_bracket(const at::Tensor& a, const at::Tensor& b) {
  check_vectors(a, "lie_bracket");
  check_vectors(b, "lie_bracket");
  return at::linalg_cross(a, b, -1);
}

at::Tensor quaternion_to_matrix(const at::Tensor& q) {
  const auto w = q.select(-1, 0);
  const auto x = q.select(-1, 1);
  const auto y = q.select(-1, 2);
  const auto z = q.select(-1, 3);
  const auto row0 =
      at::stack({1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)}, -1);
  const auto row1 =
      at::stack({2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)}, -1);
  const auto row2 =
      at::stack({2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}, -1);
  return at::stack({row0, row1, row2}, -2);
}

}  // namespace graspecmf::flow
