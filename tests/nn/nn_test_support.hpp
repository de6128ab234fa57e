#pragma once
// Shared by the nn tests: a fixture that pins LibTorch to one thread and seeds it, random
// rotations, rotating VN features, and relative errors.

#include <ATen/Parallel.h>
#include <gtest/gtest.h>
#include <torch/types.h>
#include <torch/utils.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace graspecmf::testing {

class NnTest : public ::testing::Test {
 protected:
  void SetUp() override {
    at::set_num_threads(1);
    torch::manual_seed(20240611);
  }
};

// A rotation matrix [3, 3] (float32) from a uniformly random unit quaternion of this seed.
inline torch::Tensor random_rotation(std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> normal;
  double q[4];
  double norm = 0.0;
  for (double& c : q) {
    c = normal(engine);
    norm += c * c;
  }
  norm = std::sqrt(norm);
  const double w = q[0] / norm, x = q[1] / norm, y = q[2] / norm, z = q[3] / norm;
  const double m[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                       2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                       2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
  return torch::tensor(std::vector<double>(m, m + 9), torch::kDouble)
      .view({3, 3})
      .to(torch::kFloat);
}

// g applied to every vector of v along its last axis (size 3).
inline torch::Tensor rotate(const torch::Tensor& v, const torch::Tensor& g) {
  return torch::matmul(v, g.t());
}

// ‖actual − expected‖ / ‖expected‖, in double.
inline double relative_error(const torch::Tensor& actual, const torch::Tensor& expected) {
  return (actual.to(torch::kDouble) - expected.to(torch::kDouble)).norm().item<double>() /
         expected.to(torch::kDouble).norm().item<double>();
}

}  // namespace graspecmf::testing
