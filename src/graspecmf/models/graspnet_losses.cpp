#include "graspecmf/models/graspnet_losses.hpp"

#include <ATen/ATen.h>

#include "graspecmf/nn/checks.hpp"

namespace graspecmf::models {

using nn::detail::require_shape;

namespace {

// e of control points a and b [..., 6, 3] (broadcast): the mean over the six of the L1 distance.
at::Tensor mean_l1(const at::Tensor& a, const at::Tensor& b) {
  return (a - b).abs().sum(-1).mean(-1);
}

}  // namespace

at::Tensor panda_control_points() {
  const float x = 0.05268743F, y = 0.00005996F, inner = 0.07527314F, outer = 0.10527314F;
  return at::tensor({0.0F, 0.0F, 0.0F, 0.0F, 0.0F, 0.0F, x, -y, inner, -x, y, inner, x, -y, outer,
                     -x, y, outer})
      .view({6, 3});
}

at::Tensor grasp_control_points(const flow::PoseBatch& grasps, double scale) {
  flow::check_pose_batch(grasps, "grasp_control_points");
  const auto points = (panda_control_points() * scale).to(grasps.R.options());
  return at::matmul(grasps.R.unsqueeze(1), points.view({1, 6, 3, 1})).squeeze(3) +
         grasps.p.unsqueeze(1);
}

at::Tensor pairwise_control_point_distance(const at::Tensor& a, const at::Tensor& b) {
  require_shape(a, "pairwise_control_point_distance: a", {-1, 6, 3});
  require_shape(b, "pairwise_control_point_distance: b", {-1, 6, 3});
  return mean_l1(a.unsqueeze(1), b.unsqueeze(0));
}

at::Tensor vae_loss(const at::Tensor& predicted, const at::Tensor& truth,
                    const at::Tensor& confidence, const at::Tensor& mu, const at::Tensor& logvar,
                    double kl_weight, double confidence_weight) {
  require_shape(predicted, "vae_loss: predicted", {-1, 6, 3});
  const int64_t g = predicted.size(0);
  require_shape(truth, "vae_loss: truth", {g, 6, 3});
  require_shape(confidence, "vae_loss: confidence", {g});
  require_shape(mu, "vae_loss: mu", {g, -1});
  require_shape(logvar, "vae_loss: logvar", {g, mu.size(1)});
  const auto error = mean_l1(predicted, truth);
  const auto kl = -0.5 * (1 + logvar - mu.pow(2) - logvar.exp()).sum(1);
  return (confidence * error).mean() -
         confidence_weight * confidence.clamp_min(1e-10).log().mean() + kl_weight * kl.mean();
}

at::Tensor imle_loss(const at::Tensor& predicted, const at::Tensor& truth,
                     const at::Tensor& confidence, double confidence_weight) {
  const auto distance = pairwise_control_point_distance(predicted, truth);  // [N, M]
  nn::detail::require(distance.numel() > 0, "imle_loss: predictions and truths must not be empty");
  require_shape(confidence, "imle_loss: confidence", {predicted.size(0)});
  const auto [nearest, index] = distance.min(0);
  return (confidence.index_select(0, index) * nearest).mean() -
         confidence_weight * confidence.clamp_min(1e-4).log().mean();
}

}  // namespace graspecmf::models
