#include "graspecmf/flow/prior.hpp"

#include <ATen/ATen.h>

#include <cmath>

#include "graspecmf/core/error.hpp"
#include "graspecmf/flow/so3.hpp"

namespace graspecmf::flow {

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
