#include "graspecmf/nn/checks.hpp"

#include <ATen/ATen.h>

namespace graspecmf::nn::detail {

void require_clouds(const at::Tensor& points, const std::string& what, int64_t k) {
  require_shape(points, what + ": points", {-1, -1, 3});
  const int64_t n = points.size(1);
  require(points.size(0) >= 1, what + ": empty batch (no point cloud)");
  require(n >= 1, what + ": empty point cloud");
  require(n >= k, what + ": the cloud has " + std::to_string(n) +
                      " points, fewer than k = " + std::to_string(k));
  require(at::isfinite(points).all().item<bool>(),
          what + ": the point cloud contains NaN or infinity");
}

}  // namespace graspecmf::nn::detail
