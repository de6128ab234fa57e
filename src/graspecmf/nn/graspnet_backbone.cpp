#include "graspecmf/nn/graspnet_backbone.hpp"

#include "graspecmf/nn/checks.hpp"

namespace graspecmf::nn {

using detail::require;

GraspNetBackboneImpl::GraspNetBackboneImpl(GraspNetBackboneOptions options) {
  require(options.centroids >= 4, "GraspNetBackbone: centroids must be at least 4");
  const int64_t second = options.centroids / 4;
  sa1 = register_module(
      "sa1",
      SetAbstraction(SetAbstractionOptions{options.centroids, options.radius, 64, {64, 64, 128}},
                     options.in_features));
  sa2 = register_module(
      "sa2",
      SetAbstraction(SetAbstractionOptions{second, 2 * options.radius, 128, {128, 128, 256}}, 128));
  sa3 = register_module("sa3",
                        SetAbstraction(SetAbstractionOptions{0, 0.0, 0, {256, 256, 512}}, 256));
  fc1 = register_module("fc1", torch::nn::Linear(512, 1024));
  norm1 = register_module("norm1", torch::nn::BatchNorm1d(pointnet_norm_options(1024)));
  fc2 = register_module("fc2", torch::nn::Linear(1024, 1024));
  norm2 = register_module("norm2", torch::nn::BatchNorm1d(pointnet_norm_options(1024)));
}

at::Tensor GraspNetBackboneImpl::forward(const at::Tensor& xyz, const at::Tensor& features) {
  const auto [xyz1, features1] = sa1->forward(xyz, features);
  const auto [xyz2, features2] = sa2->forward(xyz1, features1);
  const auto global = sa3->forward(xyz2, features2).second.squeeze(1);  // [B, 512]
  return norm2->forward(fc2->forward(norm1->forward(fc1->forward(global)).relu())).relu();
}

}  // namespace graspecmf::nn
