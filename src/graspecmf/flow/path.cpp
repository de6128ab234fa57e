#include "graspecmf/flow/path.hpp"

#include <ATen/ATen.h>

#include "graspecmf/core/error.hpp"
#include "graspecmf/flow/so3.hpp"

namespace graspecmf::flow {

PathPoint geodesic_path(const PoseBatch& x0, const PoseBatch& x1, const at::Tensor& t) {
  check_pose_batch(x0, "geodesic_path");
  check_pose_batch(x1, "geodesic_path");
  check_times(t, x0, "geodesic_path");
  if (x1.R.size(0) != x0.R.size(0) || x1.R.scalar_type() != x0.R.scalar_type()) {
    throw Error("geodesic_path: x0 and x1 differ in batch size or dtype");
  }
  const auto xi = so3_log(x0.R.transpose(1, 2).matmul(x1.R));  // [B,3], body frame of R0
  const auto tc = t.unsqueeze(-1);                             // [B,1]
  PathPoint point;
  point.x_t.R = x0.R.matmul(so3_exp(tc * xi));
  point.x_t.p = (1.0 - tc) * x0.p + tc * x1.p;
  point.omega = x0.R.matmul(xi.unsqueeze(-1)).squeeze(-1);
  point.v = x1.p - x0.p;
  return point;
}

}  // namespace graspecmf::flow
