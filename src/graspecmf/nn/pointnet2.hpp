#pragma once
// PointNet++ set abstraction (Qi et al. 2017), the backbone of the 6-DOF GraspNet comparison
// models (docs/method.md, "Comparison models"): farthest-point centroids, ball-query groups, a
// shared MLP per neighbour and a max over each group.

#include <ATen/core/Tensor.h>
#include <torch/nn/module.h>
#include <torch/nn/modules/batchnorm.h>
#include <torch/nn/modules/linear.h>
#include <torch/nn/pimpl.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace graspecmf::nn {

// For points [B, N, 3] (float32), the indices [B, m] (int64) of m farthest-point samples: index 0
// first, then each time the point farthest from those chosen (of equals, the lower index). No
// gradient. Throws Error on a wrong shape or m outside [1, N].
at::Tensor farthest_point_sample(const at::Tensor& points, int64_t m);

// For points [B, N, 3] and centroids [B, M, 3], the indices [B, M, nsample] (int64) of the first
// nsample points, in index order, closer than radius to each centroid, padded by repeating the
// first one found; a centroid with none gets its nearest point. Throws Error on wrong shapes, a
// non-positive radius or nsample < 1.
at::Tensor ball_query(const at::Tensor& points, const at::Tensor& centroids, double radius,
                      int64_t nsample);

// The BatchNorm options of every PointNet++ layer: ε 10⁻³ (TensorFlow's, as in the reference).
torch::nn::BatchNorm1dOptions pointnet_norm_options(int64_t width);

struct SetAbstractionOptions {
  int64_t centroids = 0;        // farthest-point centroids; 0 = one group of every point
  double radius = 0.0;          // ball-query radius (unused when centroids = 0)
  int64_t nsample = 0;          // neighbours per group (unused when centroids = 0)
  std::vector<int64_t> widths;  // the shared MLP's layer widths
};

class SetAbstractionImpl : public torch::nn::Module {
 public:
  // in_features: per-point features besides xyz (may be 0). Throws Error on an empty width list,
  // a non-positive width, negative centroids, or (with centroids > 0) a non-positive radius or
  // nsample.
  SetAbstractionImpl(SetAbstractionOptions options, int64_t in_features);

  // xyz [B, N, 3] and features [B, N, in_features] (undefined when in_features = 0) → the
  // centroids [B, M, 3] and their features [B, M, widths.back()]. Each neighbour's input is
  // [xyz − centroid ; features] (with one group: the centroid is the origin), mapped by Linear +
  // BatchNorm + ReLU layers and max-pooled over its group. Throws Error on wrong shapes or
  // centroids > N.
  std::pair<at::Tensor, at::Tensor> forward(const at::Tensor& xyz, const at::Tensor& features);

  const SetAbstractionOptions& options() const { return options_; }

  std::vector<torch::nn::Linear> linear;
  std::vector<torch::nn::BatchNorm1d> norm;

 private:
  SetAbstractionOptions options_;
  int64_t in_features_;
};
TORCH_MODULE(SetAbstraction);

}  // namespace graspecmf::nn
