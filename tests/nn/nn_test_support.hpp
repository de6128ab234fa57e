#pragma once
// Shared by the nn tests: a fixture that pins LibTorch to one thread and seeds it, random
// rotations, rotating VN features, and relative errors.

#include <ATen/Parallel.h>
#include <gtest/gtest.h>
#include <torch/types.h>
#include <torch/utils.h>

#include <cstdint>
#include <vector>

#include "graspecmf/lie/rotation_sets.hpp"

namespace graspecmf::testing {

class NnTest : public ::testing::Test {
 protected:
  void SetUp() override {
    at::set_num_threads(1);
    torch::manual_seed(20240611);
  }
};

// A Haar-random rotation matrix [3, 3] (float32) of this seed (lie::random_rotations).
inline torch::Tensor random_rotation(std::uint64_t seed) {
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> g = lie::random_rotations(1, seed)[0];
  return torch::tensor(std::vector<double>(g.data(), g.data() + 9), torch::kDouble)
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
