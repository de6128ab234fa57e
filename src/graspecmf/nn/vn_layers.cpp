#include "graspecmf/nn/vn_layers.hpp"

#include <ATen/Parallel.h>
#include <torch/csrc/autograd/custom_function.h>
#include <torch/nn/init.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "graspecmf/nn/checks.hpp"
#include "graspecmf/nn/vn_leaky_relu_math.hpp"

namespace graspecmf::nn {

namespace {

// Channels-last rows of the packed layout: 3 axis rows of W = C + D floats, q in columns [0, C),
// d in [C, W).
struct PackedLayout {
  int64_t channels;  // C
  int64_t width;     // W
  int64_t rows;      // packed rows in the tensor
  bool shared() const { return width == channels + 1 && channels != 1; }
};

// The layout of a contiguous packed tensor with C = channels.
PackedLayout packed_layout(const torch::Tensor& packed, int64_t channels) {
  const int64_t width = packed.size(-1);
  return {channels, width, packed.numel() / (3 * width)};
}

// out (3 rows of C) = VN-LeakyReLU of one packed row; `Shared` reads d from column C always.
template <bool Shared>
GRASPECMF_KERNEL void leaky_relu_row(const PackedLayout& layout, const float* __restrict row,
                                     float* __restrict out, float beta) {
  const int64_t c_count = layout.channels;
  const int64_t w = layout.width;
  GRASPECMF_CHANNELS_INDEPENDENT
  for (int64_t c = 0; c < c_count; ++c) {
    const int64_t dc = Shared ? c_count : c_count + c;
    const float qx = row[c], qy = row[w + c], qz = row[2 * w + c];
    const float dx = row[dc], dy = row[w + dc], dz = row[2 * w + dc];
    const float coefficient = detail::leaky_coefficient(qx, qy, qz, dx, dy, dz, beta);
    out[c] = qx - coefficient * dx;
    out[c_count + c] = qy - coefficient * dy;
    out[2 * c_count + c] = qz - coefficient * dz;
  }
}

// The gradient of one packed row (3 rows of W) from the output's (3 rows of C); every entry of
// grad_row is written, a shared direction's column with the sum over channels.
template <bool Shared>
GRASPECMF_KERNEL void leaky_relu_row_gradient(const PackedLayout& layout,
                                              const float* __restrict row,
                                              const float* __restrict grad_out,
                                              float* __restrict grad_row, float beta) {
  const int64_t c_count = layout.channels;
  const int64_t w = layout.width;
  float shared_x = 0.0f, shared_y = 0.0f, shared_z = 0.0f;
  GRASPECMF_CHANNELS_INDEPENDENT
  for (int64_t c = 0; c < c_count; ++c) {
    const int64_t dc = Shared ? c_count : c_count + c;
    const detail::LeakyGradient g = detail::leaky_gradient(
        row[c], row[w + c], row[2 * w + c], row[dc], row[w + dc], row[2 * w + dc], grad_out[c],
        grad_out[c_count + c], grad_out[2 * c_count + c], beta);
    grad_row[c] = g.qx;
    grad_row[w + c] = g.qy;
    grad_row[2 * w + c] = g.qz;
    if constexpr (Shared) {
      shared_x += g.dx;
      shared_y += g.dy;
      shared_z += g.dz;
    } else {
      grad_row[dc] = g.dx;
      grad_row[w + dc] = g.dy;
      grad_row[2 * w + dc] = g.dz;
    }
  }
  if constexpr (Shared) {
    grad_row[c_count] = shared_x;
    grad_row[w + c_count] = shared_y;
    grad_row[2 * w + c_count] = shared_z;
  }
}

// Rows per parallel task: about 16k floats of output each.
int64_t row_grain(int64_t channels) {
  return std::max<int64_t>(1, 16384 / (3 * channels));
}

class PackedLeakyReLU : public torch::autograd::Function<PackedLeakyReLU> {
 public:
  static torch::Tensor forward(torch::autograd::AutogradContext* ctx, const torch::Tensor& packed,
                               int64_t channels, double slope) {
    const auto input = packed.contiguous();
    ctx->save_for_backward({input});
    ctx->saved_data["channels"] = channels;
    ctx->saved_data["slope"] = slope;
    const PackedLayout layout = packed_layout(input, channels);
    auto sizes = input.sizes().vec();
    sizes.back() = channels;
    auto out = torch::empty(sizes, input.options());
    const float* in_data = input.data_ptr<float>();
    float* out_data = out.data_ptr<float>();
    const auto beta = static_cast<float>(1.0 - slope);
    at::parallel_for(0, layout.rows, row_grain(channels), [&](int64_t begin, int64_t end) {
      for (int64_t r = begin; r < end; ++r) {
        const float* row = in_data + r * 3 * layout.width;
        float* row_out = out_data + r * 3 * channels;
        if (layout.shared()) {
          leaky_relu_row<true>(layout, row, row_out, beta);
        } else {
          leaky_relu_row<false>(layout, row, row_out, beta);
        }
      }
    });
    return out;
  }

  static torch::autograd::variable_list backward(torch::autograd::AutogradContext* ctx,
                                                 torch::autograd::variable_list grad_outputs) {
    const auto input = ctx->get_saved_variables()[0];
    const int64_t channels = ctx->saved_data["channels"].toInt();
    const auto beta = static_cast<float>(1.0 - ctx->saved_data["slope"].toDouble());
    const PackedLayout layout = packed_layout(input, channels);
    const auto grad_out = grad_outputs[0].contiguous();
    auto grad_in = torch::empty_like(input);
    const float* in_data = input.data_ptr<float>();
    const float* go = grad_out.data_ptr<float>();
    float* gi = grad_in.data_ptr<float>();
    at::parallel_for(0, layout.rows, row_grain(channels), [&](int64_t begin, int64_t end) {
      for (int64_t r = begin; r < end; ++r) {
        const float* row = in_data + r * 3 * layout.width;
        float* grad_row = gi + r * 3 * layout.width;
        if (layout.shared()) {
          leaky_relu_row_gradient<true>(layout, row, go + r * 3 * channels, grad_row, beta);
        } else {
          leaky_relu_row_gradient<false>(layout, row, go + r * 3 * channels, grad_row, beta);
        }
      }
    });
    return {grad_in, torch::Tensor(), torch::Tensor()};
  }
};

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

torch::Tensor vn_leaky_relu_packed(const torch::Tensor& packed, int64_t channels, double slope) {
  detail::require(packed.defined() && packed.scalar_type() == torch::kFloat && packed.dim() >= 2 &&
                      packed.size(-2) == 3 && channels >= 1 &&
                      (packed.size(-1) == 2 * channels || packed.size(-1) == channels + 1),
                  "vn_leaky_relu_packed: packed must be a float32 tensor [..., 3, " +
                      std::to_string(channels) + " + " + std::to_string(channels) + " or 1]");
  if (!packed.is_cpu()) return vn_leaky_relu_packed_any_device(packed, channels, slope);
  return PackedLeakyReLU::apply(packed, channels, slope);
}

torch::Tensor vn_leaky_relu_packed_any_device(const torch::Tensor& packed, int64_t channels,
                                              double slope) {
  const auto q = packed.narrow(-1, 0, channels);
  const auto d = packed.narrow(-1, channels, packed.size(-1) - channels);  // C or 1 columns
  const auto dot = (q * d).sum(-2, true);
  const auto norm2 = d.pow(2).sum(-2, true) + detail::kDirectionEpsilon;
  return q - (1.0 - slope) * dot.clamp_max(0.0) / norm2 * d;
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
  return forward_channels_last(v.transpose(-1, -2)).transpose(-1, -2);
}

torch::Tensor VNLinearLeakyReLUImpl::forward_channels_last(const torch::Tensor& x,
                                                           const torch::Tensor& extra) const {
  const int64_t in = feature->weight.size(1), out = feature->weight.size(0);
  detail::require(
      x.defined() && x.scalar_type() == torch::kFloat && x.dim() >= 2 && x.size(-2) == 3 &&
          x.size(-1) >= 1 && x.size(-1) <= in,
      "VNLinearLeakyReLU: x must be a float32 tensor [..., 3, ≤ " + std::to_string(in) + "]");
  // One GEMM for both maps, then the other channels' term, then the fused activation.
  auto packed = torch::linear(x, packed_weight(0, x.size(-1)));
  if (extra.defined()) packed = packed + extra;
  return vn_leaky_relu_packed(packed, out, slope);
}

torch::Tensor VNLinearLeakyReLUImpl::packed_weight(int64_t first, int64_t count) const {
  return torch::cat(
      {feature->weight.narrow(1, first, count), direction->weight.narrow(1, first, count)});
}

}  // namespace graspecmf::nn
