// The fused EdgeConv against a per-edge implementation, the encoder's equivariance, gradients
// and input errors.

#include "graspecmf/nn/encoder.hpp"

#include <gtest/gtest.h>
#include <torch/autograd.h>

#include <cmath>
#include <vector>

#include "graspecmf/core/error.hpp"
#include "graspecmf/nn/edge_conv.hpp"
#include "graspecmf/nn/knn.hpp"
#include "nn_test_support.hpp"

namespace graspecmf::nn {
namespace {

using graspecmf::testing::random_rotation;
using graspecmf::testing::relative_error;
using graspecmf::testing::rotate;

using EncoderTest = graspecmf::testing::NnTest;

EncoderOptions small_options() {
  EncoderOptions options;
  options.widths = {8, 8, 8, 8, 8};
  options.k = 8;
  options.out_channels = 16;
  options.points = 128;
  return options;
}

// The EdgeConv layer as written in docs/method.md ("Encoder"): per edge, the layer on [V_j − V_i ;
// V_i], then the mean over the k neighbours. v is [B, N, C, 3]; returns [B, N, C_out, 3].
torch::Tensor naive_edge_layer(VNLinearLeakyReLU& layer, const torch::Tensor& v,
                               const torch::Tensor& index) {
  const int64_t b = v.size(0), n = v.size(1), k = index.size(2);
  const auto flat_index = (index + torch::arange(b).view({b, 1, 1}) * n).reshape({-1});
  const auto neighbours =
      v.reshape({b * n, v.size(2), 3}).index_select(0, flat_index).view({b, n, k, v.size(2), 3});
  const auto centre = v.unsqueeze(2).expand_as(neighbours);
  return layer(torch::cat({neighbours - centre, centre}, 3)).mean(2);
}

TEST_F(EncoderTest, FusedEdgeLayerMatchesPerEdgeLayer) {
  const int64_t b = 2, n = 40, in = 5, out = 7, k = 6;
  VNLinearLeakyReLU layer(2 * in, out);
  const auto v = torch::randn({b, n, in, 3}).requires_grad_(true);
  const auto index = knn(v.detach().reshape({b, n, -1}), k);
  const auto upstream = torch::randn({b, n, out, 3});

  const auto expected = naive_edge_layer(layer, v, index);
  const auto expected_grads = torch::autograd::grad(
      {(expected * upstream).sum()}, {v, layer->feature->weight, layer->direction->weight});

  // The encoder's path: channels last, per-point maps A = W_left, B = W_right − W_left.
  const auto split = [in](const torch::Tensor& w) {
    const auto left = w.narrow(1, 0, in);
    return std::vector<torch::Tensor>{left, w.narrow(1, in, in) - left};
  };
  const auto f = split(layer->feature->weight), d = split(layer->direction->weight);
  const auto weights = torch::cat({f[0], f[1], d[0], d[1]});
  // The fused CPU kernel, and the gathering path that other devices take.
  for (const auto aggregate : {&edge_mean_leaky_relu, &edge_mean_leaky_relu_any_device}) {
    const auto actual = aggregate(torch::linear(v.transpose(-1, -2), weights), index, layer->slope)
                            .transpose(-1, -2);
    const auto actual_grads = torch::autograd::grad(
        {(actual * upstream).sum()}, {v, layer->feature->weight, layer->direction->weight});

    EXPECT_LT(relative_error(actual, expected), 1e-5);
    for (std::size_t p = 0; p < expected_grads.size(); ++p) {
      EXPECT_LT(relative_error(actual_grads[p], expected_grads[p]), 1e-4) << "gradient " << p;
    }
  }
}

TEST_F(EncoderTest, EdgeAggregationRejectsBadIndex) {
  const auto per_point = torch::randn({1, 10, 3, 8});
  EXPECT_THROW(edge_mean_leaky_relu(per_point, torch::full({1, 10, 3}, 10, torch::kLong), 0.2),
               Error);
  EXPECT_THROW(edge_mean_leaky_relu(per_point, torch::zeros({1, 10, 3}), 0.2), Error);
  EXPECT_THROW(edge_mean_leaky_relu(torch::randn({1, 10, 3, 6}),
                                    torch::zeros({1, 10, 3}, torch::kLong), 0.2),
               Error);
}

TEST_F(EncoderTest, SmallEncoderIsEquivariant) {
  Encoder encoder(small_options());
  const auto points = torch::randn({2, 128, 3});
  const auto z = encoder(points);
  ASSERT_EQ(z.sizes(), (std::vector<int64_t>{2, 16, 3}));
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto g = random_rotation(seed);
    EXPECT_LT(relative_error(encoder(rotate(points, g)), rotate(z, g)), 1e-4) << "seed " << seed;
  }
}

TEST_F(EncoderTest, PaperSizedEncoderIsEquivariant) {
  Encoder encoder;
  EXPECT_EQ(encoder->options().k, 40);
  const auto points = torch::randn({1, 96, 3});
  const auto z = encoder(points);
  ASSERT_EQ(z.sizes(), (std::vector<int64_t>{1, 341, 3}));
  const auto g = random_rotation(5);
  EXPECT_LT(relative_error(encoder(rotate(points, g)), rotate(z, g)), 1e-4);
}

TEST_F(EncoderTest, IgnoresThePointOrder) {
  Encoder encoder(small_options());
  const auto points = torch::randn({1, 64, 3});
  const auto permuted = points.index_select(1, torch::randperm(64));
  EXPECT_LT(relative_error(encoder(permuted), encoder(points)), 1e-5);
}

TEST_F(EncoderTest, GradientsReachEveryParameter) {
  Encoder encoder(small_options());
  const auto z = encoder(torch::randn({2, 64, 3}));
  (z * torch::randn_like(z)).sum().backward();
  for (const auto& item : encoder->named_parameters()) {
    const auto& name = item.key();
    const auto& parameter = item.value();
    ASSERT_TRUE(parameter.grad().defined()) << name;
    EXPECT_TRUE(torch::isfinite(parameter.grad()).all().item<bool>()) << name;
    EXPECT_GT(parameter.grad().abs().sum().item<double>(), 0.0) << name;
  }
}

TEST_F(EncoderTest, RejectsBadInput) {
  Encoder encoder(small_options());
  EXPECT_THROW(encoder(torch::zeros({1, 0, 3})), Error);
  EXPECT_THROW(encoder(torch::zeros({0, 64, 3})), Error);
  EXPECT_THROW(encoder(torch::randn({1, 7, 3})), Error);  // fewer points than k = 8
  EXPECT_THROW(encoder(torch::randn({1, 64, 2})), Error);
  EXPECT_THROW(encoder(torch::randn({64, 3})), Error);
  EXPECT_THROW(encoder(torch::randn({1, 64, 3}, torch::kDouble)), Error);
  auto nan = torch::randn({1, 64, 3});
  nan[0][10][2] = std::nanf("");
  EXPECT_THROW(encoder(nan), Error);
  auto infinite = torch::randn({1, 64, 3});
  infinite[0][3][0] = INFINITY;
  EXPECT_THROW(encoder(infinite), Error);
  EncoderOptions empty = small_options();
  empty.widths.clear();
  EXPECT_THROW(Encoder{empty}, Error);
}

}  // namespace
}  // namespace graspecmf::nn
