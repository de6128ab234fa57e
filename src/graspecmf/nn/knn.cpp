#include "graspecmf/nn/knn.hpp"

#include <ATen/ATen.h>
#include <ATen/Parallel.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "graspecmf/nn/checks.hpp"

namespace graspecmf::nn {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// The bisection stops once at most this many keys lie between its bounds; they are sorted.
constexpr int64_t kWindow = 32;

// A neighbour candidate; candidates order by key, then by index.
struct Candidate {
  float key;
  int64_t index;
  bool operator<(const Candidate& other) const {
    return key < other.key || (key == other.key && index < other.index);
  }
};

// An int32 whose order is the order of the (non-NaN) float f, and back.
int32_t ordered_bits(float f) {
  int32_t bits = 0;
  std::memcpy(&bits, &f, sizeof bits);
  return bits >= 0 ? bits : bits ^ 0x7fffffff;
}
float from_ordered_bits(int32_t ordered) {
  const int32_t bits = ordered >= 0 ? ordered : ordered ^ 0x7fffffff;
  float f = 0.0f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// Number of keys ≤ t; a branch-free loop the compiler vectorises.
int64_t count_at_most(const float* keys, int64_t n, float t) {
  int32_t count = 0;
  for (int64_t j = 0; j < n; ++j) count += keys[j] <= t ? 1 : 0;
  return count;
}

// Writes the k (≥ 2) smallest keys' indices to out: `self` (whose key must be −∞) first, then
// the others; equal keys are taken in index order. Bisects the key value (on its ordered bit
// pattern, ≤ 32 vectorised counting passes) until few keys remain undecided, then sorts those:
// a heap of the k best was 2× slower, dominated by mispredicted branches.
void select_smallest(const float* keys, int64_t n, int64_t self, int64_t k, int64_t* out,
                     std::vector<Candidate>& window) {
  int64_t lo = ordered_bits(-kInfinity), hi = ordered_bits(kInfinity);
  int64_t count_lo = 1, count_hi = n;  // invariant: count(≤ lo) < k ≤ count(≤ hi)
  while (count_hi - count_lo > kWindow && hi - lo > 1) {
    const int64_t mid = lo + (hi - lo) / 2;
    const int64_t count = count_at_most(keys, n, from_ordered_bits(static_cast<int32_t>(mid)));
    (count < k ? lo : hi) = mid;
    (count < k ? count_lo : count_hi) = count;
  }
  const float below = from_ordered_bits(static_cast<int32_t>(lo));
  const float upto = from_ordered_bits(static_cast<int32_t>(hi));
  int64_t* next = out;
  *next++ = self;
  window.clear();
  for (int64_t j = 0; j < n; ++j) {
    if (j == self) continue;
    if (keys[j] <= below) {
      *next++ = j;
    } else if (keys[j] <= upto) {
      window.push_back({keys[j], j});
    }
  }
  const auto needed = window.begin() + (k - (next - out));
  std::partial_sort(window.begin(), needed, window.end());
  std::transform(window.begin(), needed, next, [](const Candidate& c) { return c.index; });
}

}  // namespace

at::Tensor knn(const at::Tensor& features, int64_t k) {
  detail::require_shape(features, "knn: features", {-1, -1, -1});
  const int64_t batch = features.size(0);
  const int64_t n = features.size(1);
  detail::require(k >= 1 && k <= n,
                  "knn: k must lie in [1, " + std::to_string(n) + "], got " + std::to_string(k));
  at::NoGradGuard no_grad;
  const auto x = features.detach().contiguous();
  detail::require(at::isfinite(x).all().item<bool>(), "knn: features contain NaN or infinity");

  if (!x.is_cpu()) return knn_any_device(x, k);

  const auto squared_norms = x.pow(2).sum(-1).contiguous();
  const auto inner = at::bmm(x, x.transpose(1, 2)).contiguous();
  auto index = at::empty({batch, n, k}, x.options().dtype(at::kLong));
  const float* norms_data = squared_norms.data_ptr<float>();
  const float* inner_data = inner.data_ptr<float>();
  int64_t* index_data = index.data_ptr<int64_t>();

  // Row i ranks its neighbours j by ‖x_j‖² − 2 x_i·x_j, which is ‖x_i − x_j‖² less a constant.
  at::parallel_for(0, batch * n, 64, [&](int64_t begin, int64_t end) {
    std::vector<float> keys(static_cast<std::size_t>(n));
    std::vector<Candidate> window;
    for (int64_t row = begin; row < end; ++row) {
      const int64_t self = row % n;
      const float* products = inner_data + row * n;
      const float* norms = norms_data + (row / n) * n;
      for (int64_t j = 0; j < n; ++j) keys[j] = norms[j] - 2.0f * products[j];
      keys[self] = -kInfinity;
      int64_t* out = index_data + row * k;
      if (k == 1) {
        out[0] = self;
      } else {
        select_smallest(keys.data(), n, self, k, out, window);
      }
    }
  });
  return index;
}

at::Tensor knn_any_device(const at::Tensor& features, int64_t k) {
  at::NoGradGuard no_grad;
  const auto x = features.detach();
  auto keys = x.pow(2).sum(-1).unsqueeze(1) - 2.0 * at::bmm(x, x.transpose(1, 2));
  keys.diagonal(0, 1, 2).fill_(-kInfinity);  // the row itself first
  return std::get<1>(keys.topk(k, -1, /*largest=*/false, /*sorted=*/true));
}

}  // namespace graspecmf::nn
