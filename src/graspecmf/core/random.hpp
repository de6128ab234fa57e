#pragma once
// Seeded pseudo-random numbers with distributions written here, so a seed gives the same stream on
// every standard library (std::*_distribution is implementation-defined).

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace graspecmf {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  // 64 uniformly random bits.
  std::uint64_t next_u64() { return engine_(); }
  // Uniform in [0, 1) with 53 random bits.
  double uniform();
  // Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Standard normal N(0, 1) (Box–Muller; the second value of each pair is kept for the next call).
  double normal();
  // Uniform integer in [0, n) without modulo bias; n must be > 0.
  std::size_t index(std::size_t n);

  // Shuffles values in place (Fisher–Yates, from the back), every order equally likely.
  template <typename T>
  void shuffle(std::vector<T>& values) {
    for (std::size_t i = values.size(); i > 1; --i) std::swap(values[i - 1], values[index(i)]);
  }

  // The complete state as text, and back: a restored generator continues the same stream (for
  // resumable jobs). restore throws Error on text that state() did not produce.
  std::string state() const;
  void restore(const std::string& text);

 private:
  std::mt19937_64 engine_;
  bool has_spare_normal_ = false;
  double spare_normal_ = 0.0;
};

}  // namespace graspecmf
