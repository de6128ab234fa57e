#include "graspecmf/nn/edge_conv.hpp"

#include <ATen/ATen.h>
#include <ATen/Parallel.h>
#include <torch/csrc/autograd/custom_function.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "graspecmf/nn/checks.hpp"
#include "graspecmf/nn/gather_rows.hpp"
#include "graspecmf/nn/vn_layers.hpp"
#include "graspecmf/nn/vn_leaky_relu_math.hpp"

namespace graspecmf::nn {

namespace {

// Per point, per_point holds 3 axis rows of 4C floats: [A_f V | B_f V | A_d V | B_d V]. For the
// edge (i, j), q = A_f V_j + B_f V_i and d = A_d V_j + B_d V_i.
struct EdgeLayout {
  int64_t channels;  // C
  int64_t row;       // 4C, the stride between axis rows
  int64_t point;     // 12C, the stride between points
};

// Adds the response of edge (i, j) for channels [0, C) to acc (3 rows of C), unscaled.
GRASPECMF_KERNEL void add_edge_response(const EdgeLayout& layout, const float* __restrict pj,
                                        const float* __restrict pi, float* __restrict acc,
                                        float beta) {
  const int64_t c_count = layout.channels;
  const int64_t r = layout.row;
  GRASPECMF_CHANNELS_INDEPENDENT
  for (int64_t c = 0; c < c_count; ++c) {
    const float qx = pj[c] + pi[c_count + c];
    const float qy = pj[r + c] + pi[r + c_count + c];
    const float qz = pj[2 * r + c] + pi[2 * r + c_count + c];
    const float dx = pj[2 * c_count + c] + pi[3 * c_count + c];
    const float dy = pj[r + 2 * c_count + c] + pi[r + 3 * c_count + c];
    const float dz = pj[2 * r + 2 * c_count + c] + pi[2 * r + 3 * c_count + c];
    const float coefficient = detail::leaky_coefficient(qx, qy, qz, dx, dy, dz, beta);
    acc[c] += qx - coefficient * dx;
    acc[c_count + c] += qy - coefficient * dy;
    acc[2 * c_count + c] += qz - coefficient * dz;
  }
}

// Back-propagates grad (3 rows of C, already divided by k) through edge (i, j) for channels
// [c0, c1): adds ∂/∂q to the A_f rows of gj and the B_f rows of gi, ∂/∂d to A_d and B_d.
GRASPECMF_KERNEL void add_edge_gradient(const EdgeLayout& layout, int64_t c0, int64_t c1,
                                        const float* __restrict pj, const float* __restrict pi,
                                        const float* __restrict grad, float* __restrict gj,
                                        float* __restrict gi, float beta) {
  const int64_t c_count = layout.channels;
  const int64_t r = layout.row;
  GRASPECMF_CHANNELS_INDEPENDENT
  for (int64_t c = c0; c < c1; ++c) {
    const float qx = pj[c] + pi[c_count + c];
    const float qy = pj[r + c] + pi[r + c_count + c];
    const float qz = pj[2 * r + c] + pi[2 * r + c_count + c];
    const float dx = pj[2 * c_count + c] + pi[3 * c_count + c];
    const float dy = pj[r + 2 * c_count + c] + pi[r + 3 * c_count + c];
    const float dz = pj[2 * r + 2 * c_count + c] + pi[2 * r + 3 * c_count + c];
    const detail::LeakyGradient g = detail::leaky_gradient(
        qx, qy, qz, dx, dy, dz, grad[c], grad[c_count + c], grad[2 * c_count + c], beta);
    gj[c] += g.qx;
    gj[r + c] += g.qy;
    gj[2 * r + c] += g.qz;
    gi[c_count + c] += g.qx;
    gi[r + c_count + c] += g.qy;
    gi[2 * r + c_count + c] += g.qz;
    gj[2 * c_count + c] += g.dx;
    gj[r + 2 * c_count + c] += g.dy;
    gj[2 * r + 2 * c_count + c] += g.dz;
    gi[3 * c_count + c] += g.dx;
    gi[r + 3 * c_count + c] += g.dy;
    gi[2 * r + 3 * c_count + c] += g.dz;
  }
}

class EdgeMeanLeakyReLU : public torch::autograd::Function<EdgeMeanLeakyReLU> {
 public:
  static at::Tensor forward(torch::autograd::AutogradContext* ctx, const at::Tensor& per_point,
                            const at::Tensor& index, double slope) {
    const auto points = per_point.contiguous();
    const auto neighbours = index.contiguous();
    ctx->save_for_backward({points, neighbours});
    ctx->saved_data["slope"] = slope;

    const int64_t batch = points.size(0);
    const int64_t n = points.size(1);
    const int64_t k = neighbours.size(2);
    const EdgeLayout layout{points.size(3) / 4, points.size(3), 3 * points.size(3)};
    auto out = at::empty({batch, n, 3, layout.channels}, points.options());
    const float* pp = points.data_ptr<float>();
    const int64_t* idx = neighbours.data_ptr<int64_t>();
    float* out_data = out.data_ptr<float>();
    const auto beta = static_cast<float>(1.0 - slope);
    const float inv_k = 1.0f / static_cast<float>(k);

    at::parallel_for(0, batch * n, 16, [&](int64_t begin, int64_t end) {
      for (int64_t row = begin; row < end; ++row) {
        const float* pi = pp + row * layout.point;
        const float* pb = pp + (row / n) * n * layout.point;
        float* acc = out_data + row * 3 * layout.channels;
        std::fill(acc, acc + 3 * layout.channels, 0.0f);
        for (int64_t m = 0; m < k; ++m) {
          add_edge_response(layout, pb + idx[row * k + m] * layout.point, pi, acc, beta);
        }
        for (int64_t e = 0; e < 3 * layout.channels; ++e) acc[e] *= inv_k;
      }
    });
    return out;
  }

  static torch::autograd::variable_list backward(torch::autograd::AutogradContext* ctx,
                                                 torch::autograd::variable_list grad_outputs) {
    const auto saved = ctx->get_saved_variables();
    const auto& points = saved[0];
    const auto& neighbours = saved[1];
    const double slope = ctx->saved_data["slope"].toDouble();
    const int64_t batch = points.size(0);
    const int64_t n = points.size(1);
    const int64_t k = neighbours.size(2);
    const EdgeLayout layout{points.size(3) / 4, points.size(3), 3 * points.size(3)};
    const int64_t c_count = layout.channels;

    const auto grad_out = (grad_outputs[0] / static_cast<double>(k)).contiguous();
    auto grad_points = at::zeros_like(points);
    const float* pp = points.data_ptr<float>();
    const int64_t* idx = neighbours.data_ptr<int64_t>();
    const float* go = grad_out.data_ptr<float>();
    float* gp = grad_points.data_ptr<float>();
    const auto beta = static_cast<float>(1.0 - slope);

    // Threads own channel ranges, so the scatter into neighbours' rows never races.
    at::parallel_for(0, batch * c_count, 8, [&](int64_t begin, int64_t end) {
      for (int64_t b = begin / c_count; b * c_count < end; ++b) {
        const int64_t c0 = std::max<int64_t>(begin - b * c_count, 0);
        const int64_t c1 = std::min<int64_t>(end - b * c_count, c_count);
        const float* pb = pp + b * n * layout.point;
        float* gb = gp + b * n * layout.point;
        for (int64_t i = 0; i < n; ++i) {
          const int64_t row = b * n + i;
          for (int64_t m = 0; m < k; ++m) {
            const int64_t j = idx[row * k + m];
            add_edge_gradient(layout, c0, c1, pb + j * layout.point, pb + i * layout.point,
                              go + row * 3 * c_count, gb + j * layout.point, gb + i * layout.point,
                              beta);
          }
        }
      }
    });
    return {grad_points, at::Tensor(), at::Tensor()};
  }
};

}  // namespace

at::Tensor edge_mean_leaky_relu(const at::Tensor& per_point, const at::Tensor& index,
                                double slope) {
  detail::require_shape(per_point, "edge_mean_leaky_relu: per_point", {-1, -1, 3, -1});
  detail::require(per_point.size(3) % 4 == 0 && per_point.size(3) > 0,
                  "edge_mean_leaky_relu: per_point's last axis must hold 4C values, got " +
                      std::to_string(per_point.size(3)));
  detail::require(
      index.defined() && index.scalar_type() == at::kLong && index.dim() == 3 &&
          index.size(0) == per_point.size(0) && index.size(1) == per_point.size(1) &&
          index.size(2) >= 1 && index.device() == per_point.device(),
      "edge_mean_leaky_relu: index must be an int64 tensor [B, N, k] matching per_point and on its "
      "device");
  detail::require(index.numel() == 0 || (index.min().item<int64_t>() >= 0 &&
                                         index.max().item<int64_t>() < per_point.size(1)),
                  "edge_mean_leaky_relu: index holds a point outside [0, N)");
  if (!per_point.is_cpu()) return edge_mean_leaky_relu_any_device(per_point, index, slope);
  return EdgeMeanLeakyReLU::apply(per_point, index, slope);
}

at::Tensor edge_mean_leaky_relu_any_device(const at::Tensor& per_point, const at::Tensor& index,
                                           double slope) {
  const int64_t c = per_point.size(3) / 4;
  const auto neighbours = gather_rows(per_point, index);  // [B, N, k, 3, 4C]
  const auto centre = per_point.unsqueeze(2);
  const auto q = neighbours.narrow(-1, 0, c) + centre.narrow(-1, c, c);
  const auto d = neighbours.narrow(-1, 2 * c, c) + centre.narrow(-1, 3 * c, c);
  return vn_leaky_relu_packed_any_device(at::cat({q, d}, -1), c, slope).mean(2);
}

}  // namespace graspecmf::nn
