#pragma once
// The VN-LeakyReLU of one vector channel and its gradient (docs/method.md, "Vector-neuron layers"),
// inlined into the fused kernels of vn_layers.cpp and edge_conv.cpp so that their channel loops
// vectorise.

#include <algorithm>

// A kernel's channels touch disjoint entries, so its channel loop carries no dependence; GCC
// cannot see it through runtime row strides and would not vectorise it. The kernels are also
// compiled for AVX2 and picked at load time (25 % faster than SSE2 here).
#if defined(__GNUC__) && !defined(__clang__)
#define GRASPECMF_CHANNELS_INDEPENDENT _Pragma("GCC ivdep")
#else
#define GRASPECMF_CHANNELS_INDEPENDENT
#endif
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define GRASPECMF_KERNEL __attribute__((target_clones("avx2", "default")))
#else
#define GRASPECMF_KERNEL
#endif

namespace graspecmf::nn::detail {

// ε in the direction's squared norm, as in the reference.
inline constexpr float kDirectionEpsilon = 1e-6f;

// out = q − c·d for the c returned here, with beta = 1 − slope.
inline float leaky_coefficient(float qx, float qy, float qz, float dx, float dy, float dz,
                               float beta) {
  const float dot = qx * dx + qy * dy + qz * dz;
  const float norm2 = dx * dx + dy * dy + dz * dz + kDirectionEpsilon;
  return beta * std::min(dot, 0.0f) / norm2;  // branch-free: vectorises
}

// The gradients of out with respect to q and d, given the upstream gradient g.
struct LeakyGradient {
  float qx, qy, qz, dx, dy, dz;
};

inline LeakyGradient leaky_gradient(float qx, float qy, float qz, float dx, float dy, float dz,
                                    float gx, float gy, float gz, float beta) {
  const float dot = qx * dx + qy * dy + qz * dz;
  const float inv_norm2 = 1.0f / (dx * dx + dy * dy + dz * dz + kDirectionEpsilon);
  // out = q − w·s·d with s = ⟨q,d⟩/(‖d‖²+ε) and w = β where ⟨q,d⟩ < 0, else 0.
  const float w = dot < 0.0f ? beta : 0.0f;
  const float s = dot * inv_norm2;
  const float gd_n = (gx * dx + gy * dy + gz * dz) * inv_norm2;  // ⟨g,d⟩/(‖d‖²+ε)
  // ∂/∂q = g − w⟨g,d⟩/n·d;  ∂/∂d = −w(s·g + ⟨g,d⟩/n·q − 2s⟨g,d⟩/n·d).
  return {gx - w * gd_n * dx,
          gy - w * gd_n * dy,
          gz - w * gd_n * dz,
          -w * (s * gx + gd_n * qx - 2.0f * s * gd_n * dx),
          -w * (s * gy + gd_n * qy - 2.0f * s * gd_n * dy),
          -w * (s * gz + gd_n * qz - 2.0f * s * gd_n * dz)};
}

}  // namespace graspecmf::nn::detail
