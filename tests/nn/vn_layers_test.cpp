// VN layers: equivariance, the LeakyReLU definition, shape errors; kNN against brute force.

#include "graspecmf/nn/vn_layers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "graspecmf/core/error.hpp"
#include "graspecmf/nn/knn.hpp"
#include "nn_test_support.hpp"

namespace graspecmf::nn {
namespace {

using graspecmf::testing::NnTest;
using graspecmf::testing::random_rotation;
using graspecmf::testing::relative_error;
using graspecmf::testing::rotate;

using VnLayersTest = NnTest;
using KnnTest = NnTest;

// docs/method.md's VN-LeakyReLU written with tensor operations, vectors along the last axis of
// [..., C, 3]; d has q's channels or one (broadcast). The fused layer must match it.
torch::Tensor reference_leaky_relu(const torch::Tensor& q, const torch::Tensor& d, double slope) {
  const auto dot = (q * d).sum(-1, true);
  const auto coefficient = dot.clamp_max(0.0) / ((d * d).sum(-1, true) + 1e-6) * (1.0 - slope);
  return q - coefficient * d;
}

// Packs q [R, C, 3] and d [R, D, 3] channels last, [R, 3, C + D], as vn_leaky_relu_packed wants.
torch::Tensor pack(const torch::Tensor& q, const torch::Tensor& d) {
  return torch::cat({q, d}, 1).transpose(1, 2).contiguous();
}

TEST_F(VnLayersTest, VNLinearIsEquivariant) {
  VNLinear layer(7, 5);
  const auto v = torch::randn({4, 16, 7, 3});
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto g = random_rotation(seed);
    EXPECT_LT(relative_error(layer(rotate(v, g)), rotate(layer(v), g)), 1e-5);
  }
}

TEST_F(VnLayersTest, VNLinearLeakyReLUIsEquivariant) {
  for (const bool shared : {false, true}) {
    VNLinearLeakyReLU layer(9, 6, shared);
    const auto v = torch::randn({32, 9, 3});
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const auto g = random_rotation(seed);
      EXPECT_LT(relative_error(layer(rotate(v, g)), rotate(layer(v), g)), 1e-5)
          << "shared direction " << shared;
    }
  }
}

TEST_F(VnLayersTest, LeakyReLUKeepsThePositiveHalfSpaceAndShrinksTheOther) {
  const auto q = torch::randn({200, 4, 3});
  const auto d = torch::randn({200, 4, 3});
  const double slope = 0.2;
  const auto out = vn_leaky_relu_packed(pack(q, d), 4, slope).transpose(1, 2);
  const auto dot = (q * d).sum(-1);
  const auto out_dot = (out * d).sum(-1);
  const auto positive = dot >= 0;
  ASSERT_GT(positive.sum().item<int64_t>(), 0);
  ASSERT_GT((~positive).sum().item<int64_t>(), 0);
  // Where ⟨q,d⟩ ≥ 0 the feature passes; elsewhere its d component is scaled by the slope.
  EXPECT_TRUE(torch::equal(out.index({positive}), q.index({positive})));
  EXPECT_TRUE(
      torch::allclose(out_dot.index({~positive}), slope * dot.index({~positive}), 1e-4, 1e-5));
  const auto d_hat = d / d.norm(2, -1, true);
  const auto perpendicular = [&](const torch::Tensor& x) {
    return x - (x * d_hat).sum(-1, true) * d_hat;
  };
  EXPECT_TRUE(torch::allclose(perpendicular(out), perpendicular(q), 1e-4, 1e-5));
}

TEST_F(VnLayersTest, SharedDirectionBroadcastsOneVector) {
  VNLinearLeakyReLU layer(5, 4, /*shared_direction=*/true);
  EXPECT_EQ(layer->direction->weight.sizes(), (std::vector<int64_t>{1, 5}));
  const auto v = torch::randn({3, 5, 3});
  const auto q = layer->feature(v);
  const auto d = layer->direction(v);
  EXPECT_TRUE(torch::allclose(layer(v), reference_leaky_relu(q, d, layer->slope), 1e-5, 1e-6));
}

TEST_F(VnLayersTest, ChannelsLastPrefixPlusTheRestsTermMatchesTheFullInput) {
  VNLinearLeakyReLU layer(7, 4);
  const auto v = torch::randn({6, 7, 3});
  const auto x = v.transpose(1, 2);  // [6, 3, 7]
  const auto rest = torch::linear(x.narrow(2, 3, 4), layer->packed_weight(3, 4));
  const auto split = layer->forward_channels_last(x.narrow(2, 0, 3), rest);
  EXPECT_TRUE(torch::allclose(split.transpose(1, 2), layer(v), 1e-5, 1e-6));
  EXPECT_TRUE(torch::allclose(layer->forward_channels_last(x).transpose(1, 2), layer(v)));
  EXPECT_THROW(layer->forward_channels_last(torch::randn({6, 3, 8})), Error);
  EXPECT_THROW(layer->forward_channels_last(torch::randn({6, 7, 3})), Error);
}

TEST_F(VnLayersTest, PackedLeakyReLUMatchesTheReferenceAndItsGradients) {
  // The CPU kernel, and the tensor-operation path that other devices take.
  for (const auto leaky_relu : {&vn_leaky_relu_packed, &vn_leaky_relu_packed_any_device}) {
    for (const int64_t directions : {int64_t{7}, int64_t{1}}) {
      const auto q = torch::randn({50, 7, 3}, torch::requires_grad());
      const auto d = torch::randn({50, directions, 3}, torch::requires_grad());
      const auto upstream = torch::randn({50, 7, 3});
      const auto expected = reference_leaky_relu(q, d, 0.2);
      expected.backward(upstream);
      const auto packed = pack(q.detach(), d.detach()).requires_grad_();
      const auto out = leaky_relu(packed, 7, 0.2);
      EXPECT_TRUE(torch::allclose(out.transpose(1, 2), expected, 1e-5, 1e-6)) << directions;
      out.backward(upstream.transpose(1, 2).contiguous());
      const auto grad = packed.grad().transpose(1, 2);  // [50, 7 + D, 3]
      EXPECT_TRUE(torch::allclose(grad.narrow(1, 0, 7), q.grad(), 1e-4, 1e-5)) << directions;
      EXPECT_TRUE(torch::allclose(grad.narrow(1, 7, directions), d.grad(), 1e-4, 1e-5))
          << directions;
    }
  }
  EXPECT_THROW(vn_leaky_relu_packed(torch::randn({5, 3, 9}), 4, 0.2), Error);
  EXPECT_THROW(vn_leaky_relu_packed(torch::randn({5, 2, 8}), 4, 0.2), Error);
  EXPECT_THROW(vn_leaky_relu_packed(torch::randn({5, 3, 8}, torch::kDouble), 4, 0.2), Error);
}

TEST_F(VnLayersTest, InitialisationIsUniformInTheFanInBound) {
  VNLinear layer(64, 128);
  const double bound = 1.0 / std::sqrt(64.0);
  EXPECT_LE(layer->weight.abs().max().item<double>(), bound);
  EXPECT_GT(layer->weight.abs().max().item<double>(), 0.9 * bound);
  EXPECT_EQ(layer->parameters().size(), 1u);
}

TEST_F(VnLayersTest, MeanPoolIsEquivariant) {
  const auto v = torch::randn({2, 10, 4, 3});
  const auto g = random_rotation(7);
  EXPECT_LT(relative_error(vn_mean_pool(rotate(v, g), 1), rotate(vn_mean_pool(v, 1), g)), 1e-6);
}

TEST_F(VnLayersTest, RejectsWrongShapes) {
  VNLinear linear(4, 2);
  EXPECT_THROW(linear(torch::randn({5, 4, 2})), Error);
  EXPECT_THROW(linear(torch::randn({5, 3, 3})), Error);
  EXPECT_THROW(linear(torch::randn({3})), Error);
  EXPECT_THROW(linear(torch::randn({5, 4, 3}, torch::kDouble)), Error);
  VNLinearLeakyReLU block(4, 2);
  EXPECT_THROW(block(torch::randn({5, 2, 3})), Error);
  EXPECT_THROW(VNLinear(0, 3), Error);
}

// Brute force in double: the row itself first, then the k − 1 nearest others (ties to the lower
// index), sorted by index.
std::vector<int64_t> brute_force_knn(const torch::Tensor& features, int64_t b, int64_t i,
                                     int64_t k) {
  const auto x = features[b].to(torch::kDouble);
  const auto distances = (x - x[i]).pow(2).sum(-1);
  std::vector<std::pair<double, int64_t>> order;
  for (int64_t j = 0; j < x.size(0); ++j) {
    if (j != i) order.emplace_back(distances[j].item<double>(), j);
  }
  std::sort(order.begin(), order.end());
  std::vector<int64_t> result{i};
  for (int64_t m = 0; m + 1 < k; ++m) result.push_back(order[static_cast<std::size_t>(m)].second);
  std::sort(result.begin() + 1, result.end());
  return result;
}

// Row i of the kNN result with the neighbours after the first (the row itself) sorted.
std::vector<int64_t> row(const torch::Tensor& index, int64_t b, int64_t i) {
  const auto r = index[b][i].contiguous();
  std::vector<int64_t> result(r.data_ptr<int64_t>(), r.data_ptr<int64_t>() + r.numel());
  std::sort(result.begin() + 1, result.end());
  return result;
}

TEST_F(KnnTest, MatchesBruteForce) {
  struct Case {
    int64_t batch, n, d, k;
  };
  for (const Case c :
       {Case{2, 64, 12, 9}, Case{1, 300, 6, 40}, Case{1, 50, 3, 1}, Case{1, 50, 3, 50}}) {
    const auto features = torch::randn({c.batch, c.n, c.d});
    // The CPU selection, and the topk path that other devices take.
    for (const auto select : {&knn, &knn_any_device}) {
      const auto index = select(features, c.k);
      ASSERT_EQ(index.sizes(), (std::vector<int64_t>{c.batch, c.n, c.k}));
      ASSERT_EQ(index.scalar_type(), torch::kLong);
      for (int64_t b = 0; b < c.batch; ++b) {
        for (int64_t i = 0; i < c.n; ++i) {
          ASSERT_EQ(row(index, b, i), brute_force_knn(features, b, i, c.k))
              << "n " << c.n << " k " << c.k << " row " << b << ", " << i;
        }
      }
    }
  }
}

TEST_F(KnnTest, BreaksTiesByTheLowerIndex) {
  // Small integer coordinates: every distance is exact in float and many are equal.
  for (const int64_t n : {80, 400}) {
    const auto features = torch::randint(-2, 3, {1, n, 2}).to(torch::kFloat);
    const auto index = knn(features, 40);
    for (int64_t i = 0; i < n; ++i) {
      ASSERT_EQ(row(index, 0, i), brute_force_knn(features, 0, i, 40)) << "n " << n << " row " << i;
    }
  }
}

TEST_F(KnnTest, NeighbourSetsAreRotationInvariant) {
  const int64_t n = 128, channels = 8, k = 10;
  const auto v = torch::randn({1, n, channels, 3});
  const auto g = random_rotation(11);
  const auto index = knn(v.reshape({1, n, -1}), k);
  const auto rotated = knn(rotate(v, g).reshape({1, n, -1}), k);
  const auto x = v.reshape({n, -1}).to(torch::kDouble);
  int64_t compared = 0;
  for (int64_t i = 0; i < n; ++i) {
    // Rows whose k-th and (k+1)-th distances nearly tie may legitimately differ after rounding.
    const auto sorted = std::get<0>((x - x[i]).pow(2).sum(-1).sort());
    const double gap = (sorted[k] - sorted[k - 1]).item<double>();
    if (gap < 1e-4 * sorted[k].item<double>()) continue;
    ++compared;
    EXPECT_EQ(row(index, 0, i), row(rotated, 0, i)) << i;
  }
  EXPECT_GT(compared, n * 9 / 10);
}

TEST_F(KnnTest, RejectsBadInput) {
  EXPECT_THROW(knn(torch::randn({4, 3}), 2), Error);
  EXPECT_THROW(knn(torch::randn({1, 4, 3}), 5), Error);
  EXPECT_THROW(knn(torch::randn({1, 4, 3}), 0), Error);
  EXPECT_THROW(knn(torch::randn({1, 0, 3}), 1), Error);
  auto nan = torch::randn({1, 8, 3});
  nan[0][3][1] = std::nanf("");
  EXPECT_THROW(knn(nan, 2), Error);
}

}  // namespace
}  // namespace graspecmf::nn
