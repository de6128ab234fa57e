#pragma once
// The PointNet++ backbone of 6-DOF GraspNet (Mousavian et al. 2019), shared in shape by its
// encoder and decoder (docs/method.md, "Comparison models"): three set abstractions and two
// fully connected layers to one 1024-vector per cloud.

#include <ATen/core/Tensor.h>
#include <torch/nn/module.h>
#include <torch/nn/modules/batchnorm.h>
#include <torch/nn/modules/linear.h>
#include <torch/nn/pimpl.h>

#include <cstdint>

#include "graspecmf/nn/pointnet2.hpp"

namespace graspecmf::nn {

struct GraspNetBackboneOptions {
  int64_t in_features = 0;  // per-point features besides xyz
  double radius = 0.02;  // the first ball query's radius in the cloud's units; the second's is 2×
  int64_t centroids = 128;  // the first layer's centroids; the second has a quarter
};

class GraspNetBackboneImpl : public torch::nn::Module {
 public:
  // SA(centroids, radius, 64 neighbours, [64, 64, 128]) → SA(centroids / 4, 2 radius, 128,
  // [128, 128, 256]) → SA(all, [256, 256, 512]) → Linear + BatchNorm + ReLU to 1024, twice.
  // Throws Error on a negative in_features, a non-positive radius or centroids < 4.
  explicit GraspNetBackboneImpl(GraspNetBackboneOptions options);

  // xyz [B, N, 3], features [B, N, in_features] (undefined when 0) → [B, 1024]. Throws Error on
  // wrong shapes or N < centroids.
  at::Tensor forward(const at::Tensor& xyz, const at::Tensor& features);

  SetAbstraction sa1{nullptr}, sa2{nullptr}, sa3{nullptr};
  torch::nn::Linear fc1{nullptr}, fc2{nullptr};
  torch::nn::BatchNorm1d norm1{nullptr}, norm2{nullptr};
};
TORCH_MODULE(GraspNetBackbone);

}  // namespace graspecmf::nn
