#pragma once
// Whether one method beats another on the same objects, with the uncertainty that a few dozen
// objects leave: wins and losses per object, an exact sign test and a bootstrap interval for the
// mean difference. Scores are lower-is-better (EMDs).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace graspecmf::metrics {

struct PairedComparison {
  std::size_t objects = 0;
  std::size_t wins = 0;          // objects where a < b
  std::size_t losses = 0;        // objects where a > b (the rest are ties)
  double sign_test_p = 1.0;      // two-sided exact binomial test of wins against losses
  double mean_difference = 0.0;  // mean of b − a: positive when a is better
  double ci_low = 0.0;           // 95 % percentile-bootstrap interval of that mean
  double ci_high = 0.0;
};

// A mean over objects with its 95 % percentile-bootstrap interval.
struct MeanInterval {
  double mean = 0.0;
  double low = 0.0;
  double high = 0.0;
};

// The mean of values and the interval of `resamples` bootstrap draws of them (with replacement)
// from `seed`. Throws Error if values is empty or not finite, or resamples is 0.
MeanInterval bootstrap_mean(const std::vector<double>& values, std::uint64_t seed,
                            std::size_t resamples = 10000);

// Compares scores a[i] and b[i] of the same objects; `resamples` bootstrap draws of the objects
// (with replacement) from `seed`. Throws Error if the lists differ in length, are empty, hold a
// non-finite score, or resamples is 0.
PairedComparison compare_paired(const std::vector<double>& a, const std::vector<double>& b,
                                std::uint64_t seed, std::size_t resamples = 10000);

// How many per-object wins are possible at all: on objects with a sampling floor (the EMD between
// two disjoint draws of the object's own grasps), a perfect sampler scores about the floor, so
// its wins against the baseline bound what the model can reach.
struct FloorComparison {
  std::size_t objects = 0;
  std::size_t model_wins = 0;  // objects where model < baseline
  std::size_t floor_wins = 0;  // objects where floor < baseline
  double median_excess = 0.0;  // median over the objects of model − floor
};

// Compares model[i], baseline[i] and floor[i] of the same objects. Throws Error if the lists
// differ in length, are empty or hold a non-finite score.
FloorComparison compare_with_floor(const std::vector<double>& model,
                                   const std::vector<double>& baseline,
                                   const std::vector<double>& floor);

}  // namespace graspecmf::metrics
