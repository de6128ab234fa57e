#include "graspecmf/nn/pointnet2.hpp"

#include <ATen/ATen.h>
#include <c10/core/GradMode.h>
#include <torch/nn/options/batchnorm.h>

#include <algorithm>
#include <limits>
#include <string>

#include "graspecmf/nn/checks.hpp"
#include "graspecmf/nn/gather_rows.hpp"

namespace graspecmf::nn {

using detail::require;
using detail::require_shape;

torch::nn::BatchNorm1dOptions pointnet_norm_options(int64_t width) {
  return torch::nn::BatchNorm1dOptions(width).eps(1e-3);
}

at::Tensor farthest_point_sample(const at::Tensor& points, int64_t m) {
  require_shape(points, "farthest_point_sample: points", {-1, -1, 3});
  const int64_t b = points.size(0), n = points.size(1);
  require(m >= 1 && m <= n, "farthest_point_sample: m must be in [1, " + std::to_string(n) +
                                "], got " + std::to_string(m));
  const c10::NoGradGuard no_grad;
  auto chosen = at::zeros({b, m}, points.options().dtype(at::kLong));
  auto nearest = at::full({b, n}, std::numeric_limits<float>::infinity(), points.options());
  auto last = at::zeros({b, 1}, chosen.options());
  for (int64_t i = 1; i < m; ++i) {
    const auto centre = gather_rows(points, last);  // [B, 1, 3]
    nearest = at::minimum(nearest, (points - centre).pow(2).sum(2));
    last = nearest.argmax(1, /*keepdim=*/true);  // the first of equal maxima
    chosen.select(1, i).copy_(last.squeeze(1));
  }
  return chosen;
}

at::Tensor ball_query(const at::Tensor& points, const at::Tensor& centroids, double radius,
                      int64_t nsample) {
  require_shape(points, "ball_query: points", {-1, -1, 3});
  require_shape(centroids, "ball_query: centroids", {points.size(0), -1, 3});
  require(radius > 0.0, "ball_query: radius must be positive, got " + std::to_string(radius));
  require(nsample >= 1, "ball_query: nsample must be at least 1, got " + std::to_string(nsample));
  const c10::NoGradGuard no_grad;
  const int64_t n = points.size(1);
  const auto distance = at::cdist(centroids, points).pow(2);  // [B, M, N]
  const auto order = at::arange(n, points.options().dtype(at::kLong)).expand_as(distance);
  // Points inside the ball keep their index as the key, the others rank after every index.
  const auto key = at::where(distance < radius * radius, order, order + n);
  const int64_t k = std::min(nsample, n);
  const auto first = std::get<0>(key.topk(k, 2, /*largest=*/false, /*sorted=*/true));
  // Outside entries repeat the first found; a centroid with none found takes its nearest point.
  const auto nearest = distance.argmin(2, /*keepdim=*/true);
  const auto found = first.select(2, 0).unsqueeze(2);
  const auto fill = at::where(found < n, found, nearest);
  auto index = at::where(first < n, first, fill);
  if (k < nsample) index = at::cat({index, fill.expand({-1, -1, nsample - k})}, 2);
  return index;
}

SetAbstractionImpl::SetAbstractionImpl(SetAbstractionOptions options, int64_t in_features)
    : options_(std::move(options)), in_features_(in_features) {
  require(!options_.widths.empty(), "SetAbstraction: widths must not be empty");
  require(in_features_ >= 0, "SetAbstraction: in_features must not be negative");
  require(options_.centroids >= 0, "SetAbstraction: centroids must not be negative");
  if (options_.centroids > 0) {
    require(options_.radius > 0.0, "SetAbstraction: radius must be positive");
    require(options_.nsample >= 1, "SetAbstraction: nsample must be at least 1");
  }
  int64_t width_in = 3 + in_features_;
  for (size_t l = 0; l < options_.widths.size(); ++l) {
    const int64_t width = options_.widths[l];
    require(width >= 1, "SetAbstraction: widths must be positive");
    linear.push_back(
        register_module("linear" + std::to_string(l), torch::nn::Linear(width_in, width)));
    norm.push_back(register_module("norm" + std::to_string(l),
                                   torch::nn::BatchNorm1d(pointnet_norm_options(width))));
    width_in = width;
  }
}

std::pair<at::Tensor, at::Tensor> SetAbstractionImpl::forward(const at::Tensor& xyz,
                                                              const at::Tensor& features) {
  require_shape(xyz, "SetAbstraction: xyz", {-1, -1, 3});
  const int64_t b = xyz.size(0), n = xyz.size(1);
  if (in_features_ > 0) {
    require_shape(features, "SetAbstraction: features", {b, n, in_features_});
  } else {
    require(!features.defined(), "SetAbstraction: features given to a layer without them");
  }
  require(options_.centroids <= n, "SetAbstraction: " + std::to_string(options_.centroids) +
                                       " centroids asked of " + std::to_string(n) + " points");
  at::Tensor centres, grouped;  // [B, M, 3], [B, M, S, 3 + in_features]
  if (options_.centroids == 0) {
    centres = at::zeros({b, 1, 3}, xyz.options());
    grouped = (in_features_ > 0 ? at::cat({xyz, features}, 2) : xyz).unsqueeze(1);
  } else {
    centres = gather_rows(xyz, farthest_point_sample(xyz, options_.centroids));
    const auto index = ball_query(xyz, centres, options_.radius, options_.nsample);
    const auto local = gather_rows(xyz, index) - centres.unsqueeze(2);
    grouped = in_features_ > 0 ? at::cat({local, gather_rows(features, index)}, 3) : local;
  }
  const int64_t m = grouped.size(1), s = grouped.size(2);
  auto h = grouped.reshape({b * m * s, -1});
  for (size_t l = 0; l < linear.size(); ++l) h = norm[l]->forward(linear[l]->forward(h)).relu();
  return {centres, std::get<0>(h.view({b, m, s, -1}).max(2))};
}

}  // namespace graspecmf::nn
