// SE(3)-DiffusionFields' networks at the reference's sizes: parameter counts from the layer shapes,
// an encoder whose 44 vectors rotate with the cloud, and an energy that can be differentiated twice
// in the pose (what denoising score matching needs).

#include <ATen/Parallel.h>
#include <gtest/gtest.h>
#include <torch/torch.h>

#include "graspecmf/flow/prior.hpp"
#include "graspecmf/flow/so3.hpp"
#include "graspecmf/nn/se3dif_encoder.hpp"
#include "graspecmf/nn/se3dif_energy.hpp"

namespace graspecmf::nn {
namespace {

int64_t parameter_count(const torch::nn::Module& module) {
  int64_t n = 0;
  for (const auto& p : module.parameters()) n += p.numel();
  return n;
}

class Se3DifNetworks : public ::testing::Test {
 protected:
  void SetUp() override {
    at::set_num_threads(1);
    torch::manual_seed(3);
  }
};

// Encoder: edge layer 2·3·128, lift 128·256, five blocks of 256² + 256·128 + 128² + 128² + 256·128,
// VN-ReLU 128², output 128·44. Feature network: time 132² + 132, position 3·132 + 132,
// weight-normed layers (weights, biases, gains) 267→512→512→512→245 and 512→512 four times, output
// 512·7 + 7. Head: 210·512 + 512, LayerNorm 2·512, 512 + 1.
TEST_F(Se3DifNetworks, ParameterCountsFollowTheReference) {
  EXPECT_EQ(parameter_count(*Se3DifEncoder()), 874752);
  const Se3DifEnergy energy(8.0);
  EXPECT_EQ(parameter_count(*energy->features), 1864341);
  EXPECT_EQ(parameter_count(*energy) - parameter_count(*energy->features), 109569);
}

TEST_F(Se3DifNetworks, TheEncodersVectorsRotateWithTheCloud) {
  Se3DifEncoder encoder;
  encoder->eval();
  const auto cloud = torch::randn({2, 64, 3});
  at::Generator generator = flow::make_generator(4);
  const auto R = flow::sample_prior(1, 1.0, generator).R[0];  // float32
  const auto z = encoder->forward(cloud).view({2, 44, 3});
  const auto rotated = encoder->forward(cloud.matmul(R.t())).view({2, 44, 3});
  EXPECT_LT((rotated - z.matmul(R.t())).abs().max().item<double>(),
            1e-5 * z.abs().max().item<double>());
}

TEST_F(Se3DifNetworks, TheEnergyHasSecondDerivativesInThePose) {
  Se3DifEnergy energy(8.0);
  energy->eval();
  at::Generator generator = flow::make_generator(5);
  const flow::PoseBatch x = flow::sample_prior(4, 1.0, generator);
  const auto phi = torch::cat({x.p, flow::so3_log(x.R)}, 1).requires_grad_(true);
  const auto e = energy->forward({flow::so3_exp(phi.slice(1, 3, 6)), phi.slice(1, 0, 3)},
                                 torch::full({4}, 0.5), torch::randn({4, 132}));
  ASSERT_EQ(e.sizes(), (std::vector<int64_t>{4}));
  const auto gradient = torch::autograd::grad({e.sum()}, {phi}, {}, true, true)[0];
  const auto second = torch::autograd::grad({gradient.pow(2).sum()}, {phi})[0];
  EXPECT_GT(gradient.abs().max().item<double>(), 0.0);
  EXPECT_GT(second.abs().max().item<double>(), 0.0);
  EXPECT_TRUE(torch::isfinite(second).all().item<bool>());
}

// Dropout masks come from the generator passed in, so a seed repeats them; without a generator, or
// in eval mode, there is no dropout.
TEST_F(Se3DifNetworks, DropoutMasksComeFromTheGivenGenerator) {
  Se3DifEnergy energy(8.0);
  at::Generator poses = flow::make_generator(6);
  const flow::PoseBatch x = flow::sample_prior(4, 1.0, poses);
  const auto t = torch::full({4}, 0.5);
  const auto z = torch::randn({4, 132});
  at::Generator a = flow::make_generator(1), b = flow::make_generator(1),
                c = flow::make_generator(2);
  const auto ea = energy->forward(x, t, z, &a);
  EXPECT_TRUE(torch::equal(ea, energy->forward(x, t, z, &b)));
  EXPECT_FALSE(torch::equal(ea, energy->forward(x, t, z, &c)));
  const auto plain = energy->forward(x, t, z);
  energy->eval();
  EXPECT_TRUE(torch::equal(plain, energy->forward(x, t, z, &c)));
}

}  // namespace
}  // namespace graspecmf::nn
