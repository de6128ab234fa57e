#include "graspecmf/nn/se3dif_energy.hpp"

#include <torch/torch.h>

#include <cmath>

#include "graspecmf/flow/pose_batch.hpp"

namespace graspecmf::nn {
namespace {

constexpr int64_t kLatent = 132;
constexpr int64_t kWidth = 512;
constexpr int64_t kLayers = 8;
constexpr int64_t kReentry = 4;  // the layer whose input is [h ; the first layer's input]
constexpr int64_t kOutputs = 7;
constexpr int64_t kGripperPoints = 30;
constexpr double kDropout = 0.2;
constexpr double kFrequencyStd = 30.0;
constexpr std::uint64_t kGripperPointSeed = 0;

// Inverted dropout of x with masks from generator (CPU), in training only.
torch::Tensor drop(const torch::Tensor& x, bool training, at::Generator* generator) {
  if (!training || generator == nullptr) return x;
  const auto keep = at::bernoulli(torch::full(x.sizes(), 1 - kDropout), *generator);
  return x * keep.to(x.options()) / (1 - kDropout);
}

}  // namespace

WeightNormLinearImpl::WeightNormLinearImpl(int64_t in_features, int64_t out_features) {
  const torch::nn::Linear plain(in_features, out_features);  // its default initialisation
  direction = register_parameter("direction", plain->weight.detach().clone());
  gain = register_parameter("gain", plain->weight.detach().norm(2, {1}));
  bias = register_parameter("bias", plain->bias.detach().clone());
}

torch::Tensor WeightNormLinearImpl::forward(const torch::Tensor& x) const {
  const auto weight = gain.unsqueeze(1) * direction / direction.norm(2, {1}, true);
  return torch::nn::functional::linear(x, weight, bias);
}

Se3DifFeatureNetImpl::Se3DifFeatureNetImpl() {
  frequencies = register_buffer("frequencies", kFrequencyStd * torch::randn({kLatent / 2}));
  time = register_module("time", torch::nn::Linear(kLatent, kLatent));
  position = register_module("position", torch::nn::Linear(3, kLatent));
  const int64_t input = 2 * kLatent + 3;
  for (int64_t l = 0; l < kLayers; ++l) {
    const int64_t in = l == 0 ? input : kWidth;
    const int64_t out = l + 1 == kReentry ? kWidth - input : kWidth;
    layers.push_back(register_module("layer" + std::to_string(l), WeightNormLinear(in, out)));
  }
  output = register_module("output", torch::nn::Linear(kWidth, kOutputs));
}

torch::Tensor Se3DifFeatureNetImpl::forward(const torch::Tensor& x, const torch::Tensor& t,
                                            const torch::Tensor& z, at::Generator* dropout) const {
  const auto angles = 2 * M_PI * t.unsqueeze(-1) * frequencies;
  const auto time_code =
      torch::silu(time.ptr()->forward(torch::cat({angles.sin(), angles.cos()}, -1)));
  const auto position_code = torch::silu(position.ptr()->forward(x));
  const auto input =
      torch::cat({drop(z, is_training(), dropout), position_code + time_code, x}, -1);
  auto h = input;
  for (int64_t l = 0; l < kLayers; ++l) {
    if (l == kReentry) h = torch::cat({h, input}, -1);
    h = drop(torch::relu(layers[static_cast<std::size_t>(l)]->forward(h)), is_training(), dropout);
  }
  return torch::tanh(output.ptr()->forward(h));
}

Se3DifEnergyImpl::Se3DifEnergyImpl(double position_scale) {
  // Uniform in [−1, 1]³, scaled by (0.7, 0.5, 0.7) and shifted by (0, 0, 0.5) in units of
  // 1/8 m: a box round the Panda hand and fingers.
  at::Generator generator = flow::make_generator(kGripperPointSeed);
  const auto unit = 2 * torch::rand({kGripperPoints, 3}, generator) - 1;
  const auto box = unit * torch::tensor({0.7F, 0.5F, 0.7F}) + torch::tensor({0.0F, 0.0F, 0.5F});
  gripper_points = register_buffer("gripper_points", box * static_cast<float>(position_scale / 8));
  features = register_module("features", Se3DifFeatureNet());
  hidden = register_module("hidden", torch::nn::Linear(kGripperPoints * kOutputs, kWidth));
  norm = register_module("norm", torch::nn::LayerNorm(torch::nn::LayerNormOptions({kWidth})));
  energy = register_module("energy", torch::nn::Linear(kWidth, 1));
}

torch::Tensor Se3DifEnergyImpl::forward(const flow::PoseBatch& x, const torch::Tensor& t,
                                        const torch::Tensor& z, at::Generator* dropout) const {
  flow::check_pose_batch(x, "Se3DifEnergy");
  const int64_t g = x.R.size(0);
  // x_j = R q_j + p for the 30 gripper points [G, 30, 3].
  const auto points = torch::matmul(gripper_points, x.R.transpose(1, 2)) + x.p.unsqueeze(1);
  const auto psi =
      features->forward(points, t.unsqueeze(1).expand({g, kGripperPoints}),
                        z.unsqueeze(1).expand({g, kGripperPoints, z.size(-1)}), dropout);
  const auto h = torch::relu(norm.ptr()->forward(hidden.ptr()->forward(psi.reshape({g, -1}))));
  return energy.ptr()->forward(h).squeeze(-1);
}

}  // namespace graspecmf::nn
