#include "graspecmf/flow/prior.hpp"

#include <ATen/ATen.h>

#include <cmath>

#include "graspecmf/core/error.hpp"

namespace graspecmf::flow {

namespace {

// [n, 4] unit quaternions (w, x, y, z) → [n, 3, 3] rotation matrices.
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

}  // namespace

PoseBatch sample_prior(int64_t n, double position_std, at::Generator& generator,
                       at::ScalarType dtype) {
  if (n < 0) throw Error("sample_prior: negative number of poses");
  if (!std::isfinite(position_std) || position_std < 0.0) {
    throw Error("sample_prior: position_std must be finite and >= 0");
  }
  if (dtype != at::kFloat && dtype != at::kDouble) {
    throw Error("sample_prior: dtype must be float32 or float64");
  }
  // Drawn and computed in float64, then rounded: float32 rotations are orthonormal to rounding.
  const auto options = at::TensorOptions().dtype(at::kDouble);
  // A standard Gaussian in R⁴ is rotation-invariant, so its direction is uniform on S³, and a
  // uniform unit quaternion gives a Haar-uniform rotation. (Its norm is 0 with probability 0.)
  const auto g = at::randn({n, 4}, generator, options);
  const auto q = g / g.norm(2, {-1}, /*keepdim=*/true);
  PoseBatch x;
  x.R = quaternion_to_matrix(q).to(dtype);
  x.p = (position_std * at::randn({n, 3}, generator, options)).to(dtype);
  return x;
}

}  // namespace graspecmf::flow
