#include "graspecmf/nn/vn_layers.hpp"

#include <torch/nn/init.h>

#include <cmath>
#include <string>

#include "graspecmf/nn/checks.hpp"

namespace graspecmf::nn {

namespace {

constexpr double kDirectionEpsilon = 1e-6;

void require_vn_feature(const torch::Tensor& v, int64_t channels, const char* layer) {
  detail::require(v.defined() && v.dim() >= 2 && v.size(-1) == 3 && v.size(-2) == channels &&
                      v.scalar_type() == torch::kFloat,
                  std::string(layer) + ": input must be a float32 tensor [..., " +
                      std::to_string(channels) + ", 3]");
}

}  // namespace

VNLinearImpl::VNLinearImpl(int64_t in_channels, int64_t out_channels) {
  detail::require(in_channels > 0 && out_channels > 0,
                  "VNLinear: channel counts must be positive, got " + std::to_string(in_channels) +
                      " → " + std::to_string(out_channels));
  const double bound = 1.0 / std::sqrt(static_cast<double>(in_channels));
  weight = register_parameter("weight", torch::empty({out_channels, in_channels}));
  torch::nn::init::uniform_(weight, -bound, bound);
}

torch::Tensor VNLinearImpl::forward(const torch::Tensor& v) const {
  require_vn_feature(v, weight.size(1), "VNLinear");
  // Channels last, the GEMM runs over all (…, axis) rows at once.
  return torch::linear(v.transpose(-1, -2), weight).transpose(-1, -2);
}

torch::Tensor vn_leaky_relu(const torch::Tensor& q, const torch::Tensor& d, double slope,
                            int64_t vector_dim) {
  const auto dot = (q * d).sum(vector_dim, /*keepdim=*/true);
  const auto norm2 = (d * d).sum(vector_dim, /*keepdim=*/true);
  const auto coefficient = dot.clamp_max(0.0) / (norm2 + kDirectionEpsilon) * (1.0 - slope);
  return q - coefficient * d;
}

torch::Tensor vn_mean_pool(const torch::Tensor& v, int64_t dim) {
  return v.mean(dim);
}

VNLinearLeakyReLUImpl::VNLinearLeakyReLUImpl(int64_t in_channels, int64_t out_channels,
                                             bool shared_direction, double negative_slope)
    : slope(negative_slope) {
  feature = register_module("feature", VNLinear(in_channels, out_channels));
  direction =
      register_module("direction", VNLinear(in_channels, shared_direction ? 1 : out_channels));
}

torch::Tensor VNLinearLeakyReLUImpl::forward(const torch::Tensor& v) const {
  require_vn_feature(v, feature->weight.size(1), "VNLinearLeakyReLU");
  // One GEMM for both maps, channels last; the result is handed back as [..., out, 3].
  const int64_t out = feature->weight.size(0);
  const auto both =
      torch::linear(v.transpose(-1, -2), torch::cat({feature->weight, direction->weight}));
  return vn_leaky_relu(both.narrow(-1, 0, out), both.narrow(-1, out, both.size(-1) - out), slope,
                       /*vector_dim=*/-2)
      .transpose(-1, -2);
}

}  // namespace graspecmf::nn
