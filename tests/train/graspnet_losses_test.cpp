// 6-DOF GraspNet's control points and losses against hand-worked values, and IMLE's rule that a
// prediction no truth picks gets no reconstruction gradient.

#include "graspecmf/models/graspnet_losses.hpp"

#include <ATen/Parallel.h>
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cmath>

#include "graspecmf/core/error.hpp"

namespace graspecmf::models {
namespace {

class GraspNetLosses : public ::testing::Test {
 protected:
  void SetUp() override { at::set_num_threads(1); }
};

// Grasps at p with the rotation of angle a about z, [G] copies.
flow::PoseBatch turned(double a, const torch::Tensor& p) {
  const float c = static_cast<float>(std::cos(a)), s = static_cast<float>(std::sin(a));
  const auto R = torch::tensor({c, -s, 0.0F, s, c, 0.0F, 0.0F, 0.0F, 1.0F}).view({1, 3, 3});
  return {R.expand({p.size(0), 3, 3}).contiguous(), p};
}

TEST_F(GraspNetLosses, ControlPointsAreTheGripperPointsMoved) {
  const auto p = torch::tensor({0.1F, 0.2F, 0.3F}).view({1, 3});
  const auto points = grasp_control_points(turned(M_PI / 2, p), 8.0);
  ASSERT_EQ(points.sizes(), (std::vector<int64_t>{1, 6, 3}));
  // The third point (x, −y, z) turned a quarter about z is (y, x, z), then scaled and moved.
  const auto expected =
      torch::tensor({8 * 0.00005996F + 0.1F, 8 * 0.05268743F + 0.2F, 8 * 0.07527314F + 0.3F});
  EXPECT_TRUE(torch::allclose(points[0][2], expected, 1e-6, 1e-6));
  EXPECT_TRUE(torch::allclose(points[0][0], p[0]));
  EXPECT_THROW(grasp_control_points({torch::eye(3), p}, 1.0), Error);
}

TEST_F(GraspNetLosses, DistanceIsTheMeanL1OverThePoints) {
  const auto a = grasp_control_points(turned(0.3, torch::zeros({2, 3})), 1.0);
  const auto b = a + torch::tensor({0.01F, -0.02F, 0.03F});
  const auto d = pairwise_control_point_distance(a, b);
  EXPECT_TRUE(torch::allclose(d, torch::full({2, 2}, 0.06F), 1e-6, 1e-6));
  EXPECT_EQ(pairwise_control_point_distance(a, a).abs().max().item<float>(), 0.0F);
}

TEST_F(GraspNetLosses, VaeLossAddsErrorConfidenceAndKl) {
  const auto truth = grasp_control_points(turned(0.3, torch::zeros({2, 3})), 1.0);
  const auto predicted = truth + torch::tensor({0.01F, -0.02F, 0.03F});
  const auto confidence = torch::tensor({0.5F, 1.0F});
  const auto mu = torch::tensor({1.0F, 0.0F, 0.0F, 0.0F}).view({2, 2});
  const auto logvar = torch::zeros({2, 2});
  // (0.5 · 0.06 + 0.06) / 2 − 2 · (log 0.5) / 2 + 0.1 · (0.5 + 0) / 2
  const double expected = 0.045 + std::log(2.0) + 0.025;
  EXPECT_NEAR(vae_loss(predicted, truth, confidence, mu, logvar, 0.1, 2.0).item<double>(), expected,
              1e-6);
  EXPECT_NEAR(vae_loss(truth, truth, torch::ones({2}), torch::zeros({2, 2}), logvar, 0.1, 2.0)
                  .item<double>(),
              0.0, 1e-7);
  EXPECT_THROW(vae_loss(predicted, truth, torch::ones({3}), mu, logvar, 0.1, 1.0), Error);
}

TEST_F(GraspNetLosses, ImleMatchesEachTruthToItsNearestPrediction) {
  const auto p = torch::tensor({0.0F, 0.0F, 0.0F, 1.0F, 0.0F, 0.0F, 5.0F, 0.0F, 0.0F}).view({3, 3});
  const auto predicted = grasp_control_points(turned(0.0, p), 1.0).requires_grad_(true);
  // Truths near the first and second predictions; the third is nobody's nearest.
  const auto truth = grasp_control_points(
      turned(0.0, torch::tensor({0.01F, 0.0F, 0.0F, 0.98F, 0.0F, 0.0F}).view({2, 3})), 1.0);
  const auto loss = imle_loss(predicted, truth, torch::ones({3}), 1.0);
  EXPECT_NEAR(loss.item<double>(), (0.01 + 0.02) / 2, 1e-6);
  loss.backward();
  const auto grad = predicted.grad();
  EXPECT_GT(grad[0].abs().sum().item<float>(), 0.0F);
  EXPECT_GT(grad[1].abs().sum().item<float>(), 0.0F);
  EXPECT_EQ(grad[2].abs().sum().item<float>(), 0.0F);
  EXPECT_THROW(imle_loss(predicted, truth.narrow(0, 0, 0), torch::ones({3}), 1.0), Error);
}

}  // namespace
}  // namespace graspecmf::models
