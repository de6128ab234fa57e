#pragma once
// The conditional probability path of Riemannian flow matching on SO(3) × R³ (METHOD §5): the
// geodesic from a prior sample x0 to a data grasp x1 and its velocity, the regression target.

#include <ATen/core/Tensor.h>

#include "graspecmf/flow/pose_batch.hpp"

namespace graspecmf::flow {

// A point x_t of the path with its velocity: omega the spatial angular velocity (Ṙ_t = [ω]× R_t)
// and v = ṗ_t, both [B,3].
struct PathPoint {
  PoseBatch x_t;
  at::Tensor omega;
  at::Tensor v;
};

// With ξ = Log(R0ᵀ R1): R_t = R0 Exp(t ξ), p_t = (1 − t) p0 + t p1, ω = R0 ξ (= R_t ξ for every t),
// v = p1 − p0. x0, x1 and t [B] share dtype and B; throws Error otherwise. At an exact half turn
// R0ᵀ R1 the geodesic is one of the two shortest ones.
PathPoint geodesic_path(const PoseBatch& x0, const PoseBatch& x1, const at::Tensor& t);

}  // namespace graspecmf::flow
