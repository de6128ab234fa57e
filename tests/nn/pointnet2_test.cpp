// PointNet++ set abstraction: farthest points and ball queries against hand-worked examples,
// the layer's shapes, its invariance to translation, and its input errors.

#include "graspecmf/nn/pointnet2.hpp"

#include <gtest/gtest.h>
#include <torch/torch.h>

#include <vector>

#include "graspecmf/core/error.hpp"
#include "graspecmf/nn/graspnet_backbone.hpp"
#include "nn_test_support.hpp"

namespace graspecmf::nn {
namespace {

using graspecmf::testing::relative_error;

using PointNet2Test = graspecmf::testing::NnTest;

// Points 0, 1, ..., n − 1 on the x axis, as a batch of one [1, n, 3].
torch::Tensor points_on_a_line(int64_t n) {
  const auto x = torch::arange(n, torch::kFloat).view({1, n, 1});
  return torch::cat({x, torch::zeros({1, n, 2})}, 2);
}

std::vector<int64_t> as_vector(const torch::Tensor& index) {
  const auto flat = index.reshape({-1}).contiguous();
  return {flat.data_ptr<int64_t>(), flat.data_ptr<int64_t>() + flat.numel()};
}

TEST_F(PointNet2Test, FarthestPointsStartAtZeroAndBreakTiesByLowerIndex) {
  // From 0 the farthest is 9; then 4 and 5 are both 4 away from {0, 9} and 4 wins; then 2, 6 and 7
  // are 2 away from {0, 9, 4} and 2 wins.
  EXPECT_EQ(as_vector(farthest_point_sample(points_on_a_line(10), 4)),
            (std::vector<int64_t>{0, 9, 4, 2}));
  const auto cloud = torch::randn({3, 50, 3});
  const auto index = farthest_point_sample(cloud, 50);
  EXPECT_EQ(std::get<0>(index.sort(1)).equal(torch::arange(50).expand({3, 50})), true);
}

TEST_F(PointNet2Test, BallQueryTakesTheFirstInsideInIndexOrderAndPadsWithTheFirst) {
  const auto points = points_on_a_line(10);
  // Around x = 5 with radius 1.5: points 4, 5, 6 (strictly inside), padded with 4.
  const auto centroids =
      torch::tensor({5.0F, 0.0F, 0.0F, 0.0F, 0.0F, 0.0F, 20.0F, 0.0F, 0.0F}).view({1, 3, 3});
  EXPECT_EQ(as_vector(ball_query(points, centroids, 1.5, 5)),
            (std::vector<int64_t>{4, 5, 6, 4, 4,     // around 5
                                  0, 1, 0, 0, 0,     // around 0
                                  9, 9, 9, 9, 9}));  // none inside: the nearest
  // Radius 1 is strict: only the centre itself; nsample beyond N pads as well.
  EXPECT_EQ(as_vector(ball_query(points, centroids.narrow(1, 0, 1), 1.0, 12)),
            std::vector<int64_t>(12, 5));
}

TEST_F(PointNet2Test, LayersGiveTheBackboneShapes) {
  SetAbstraction sa1(SetAbstractionOptions{32, 0.3, 16, {8, 8, 16}}, 2);
  SetAbstraction sa2(SetAbstractionOptions{8, 0.6, 8, {16, 32}}, 16);
  SetAbstraction sa3(SetAbstractionOptions{0, 0.0, 0, {32, 64}}, 32);
  const auto xyz = torch::randn({2, 100, 3});
  const auto [c1, f1] = sa1->forward(xyz, torch::randn({2, 100, 2}));
  const auto [c2, f2] = sa2->forward(c1, f1);
  const auto [c3, f3] = sa3->forward(c2, f2);
  EXPECT_EQ(c1.sizes(), (std::vector<int64_t>{2, 32, 3}));
  EXPECT_EQ(f1.sizes(), (std::vector<int64_t>{2, 32, 16}));
  EXPECT_EQ(f2.sizes(), (std::vector<int64_t>{2, 8, 32}));
  EXPECT_EQ(c3.sizes(), (std::vector<int64_t>{2, 1, 3}));
  EXPECT_EQ(f3.sizes(), (std::vector<int64_t>{2, 1, 64}));
  EXPECT_EQ(c3.abs().max().item<float>(), 0.0F);
  f3.sum().backward();
  EXPECT_GT(sa1->linear[0]->weight.grad().abs().sum().item<double>(), 0.0);
}

TEST_F(PointNet2Test, LocalGroupsAreInvariantToTranslation) {
  SetAbstraction layer(SetAbstractionOptions{16, 0.8, 12, {8, 16}}, 0);
  layer->eval();
  const auto xyz = torch::randn({2, 60, 3});
  const auto shift = torch::tensor({0.3F, -2.0F, 5.0F});
  const auto [centres, features] = layer->forward(xyz, {});
  const auto [moved_centres, moved_features] = layer->forward(xyz + shift, {});
  EXPECT_LT(relative_error(moved_centres, centres + shift), 1e-6);
  EXPECT_LT(relative_error(moved_features, features), 1e-5);
}

TEST_F(PointNet2Test, BadInputIsAnError) {
  EXPECT_THROW(farthest_point_sample(torch::randn({1, 5, 3}), 6), Error);
  EXPECT_THROW(farthest_point_sample(torch::randn({1, 5, 2}), 2), Error);
  EXPECT_THROW(ball_query(torch::randn({1, 5, 3}), torch::randn({1, 2, 3}), 0.0, 4), Error);
  EXPECT_THROW(ball_query(torch::randn({1, 5, 3}), torch::randn({2, 2, 3}), 1.0, 4), Error);
  EXPECT_THROW(SetAbstraction(SetAbstractionOptions{4, 0.1, 4, {}}, 0), Error);
  EXPECT_THROW(SetAbstraction(SetAbstractionOptions{4, -0.1, 4, {8}}, 0), Error);
  SetAbstraction layer(SetAbstractionOptions{8, 0.5, 4, {8}}, 1);
  EXPECT_THROW(layer->forward(torch::randn({1, 5, 3}), torch::randn({1, 5, 1})), Error);
  EXPECT_THROW(layer->forward(torch::randn({1, 9, 3}), {}), Error);
}

TEST_F(PointNet2Test, GraspNetBackboneHasTheReferenceShapes) {
  GraspNetBackbone backbone(GraspNetBackboneOptions{2, 0.5, 16});
  const auto out = backbone->forward(torch::randn({3, 200, 3}), torch::randn({3, 200, 2}));
  EXPECT_EQ(out.sizes(), (std::vector<int64_t>{3, 1024}));
  EXPECT_GE(out.min().item<float>(), 0.0F);
  // The decoder's backbone in the spec's layer shapes (SA1 5 → 64 → 64 → 128, SA2 131 → 128 →
  // 128 → 256, SA3 259 → 256 → 256 → 512, FC 512 → 1024 → 1024), every Linear with its bias and
  // every BatchNorm with its scale and shift. The centroid counts carry no weights.
  int64_t parameters = 0;
  for (const auto& p : backbone->parameters()) parameters += p.numel();
  EXPECT_EQ(parameters, 1925824);
  EXPECT_THROW(GraspNetBackbone(GraspNetBackboneOptions{2, 0.5, 3}), Error);
  EXPECT_THROW(GraspNetBackbone(GraspNetBackboneOptions{2, 0.0, 16}), Error);
}

}  // namespace
}  // namespace graspecmf::nn
