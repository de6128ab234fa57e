#include "graspecmf/metrics/paired_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <numeric>
#include <string>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/random.hpp"

namespace graspecmf::metrics {

namespace {

// P(X ≤ k) for X ~ Binomial(m, 1/2), summed in log space so that large m cannot overflow.
double binomial_half_cdf(std::size_t k, std::size_t m) {
  const double log_half_m = static_cast<double>(m) * std::log(0.5);
  const double log_m_factorial = std::lgamma(static_cast<double>(m) + 1.0);
  double total = 0.0;
  for (std::size_t i = 0; i <= k; ++i) {
    total += std::exp(log_m_factorial - std::lgamma(static_cast<double>(i) + 1.0) -
                      std::lgamma(static_cast<double>(m - i) + 1.0) + log_half_m);
  }
  return total;
}

// The value at fraction q of sorted values (nearest rank).
double quantile(const std::vector<double>& sorted, double q) {
  const auto last = static_cast<double>(sorted.size() - 1);
  return sorted[static_cast<std::size_t>(std::lround(q * last))];
}

// Throws Error, naming `caller`, unless the lists are equally long, non-empty and finite.
void check_scores(const char* caller, std::initializer_list<const std::vector<double>*> lists) {
  const std::string name(caller);
  for (const std::vector<double>* list : lists) {
    if (list->size() != (*lists.begin())->size()) {
      throw Error(name + ": the score lists differ in length");
    }
    if (list->empty()) throw Error(name + ": no objects to compare");
    if (!std::all_of(list->begin(), list->end(), [](double x) { return std::isfinite(x); })) {
      throw Error(name + ": a score is NaN or infinite");
    }
  }
}

}  // namespace

MeanInterval bootstrap_mean(const std::vector<double>& values, std::uint64_t seed,
                            std::size_t resamples) {
  check_scores("bootstrap_mean", {&values});
  if (resamples == 0) throw Error("bootstrap_mean: resamples must be positive");
  const auto n = static_cast<double>(values.size());
  Rng rng(seed);
  std::vector<double> means(resamples);
  for (double& mean : means) {
    double sum = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) sum += values[rng.index(values.size())];
    mean = sum / n;
  }
  std::sort(means.begin(), means.end());
  return {std::accumulate(values.begin(), values.end(), 0.0) / n, quantile(means, 0.025),
          quantile(means, 0.975)};
}

PairedComparison compare_paired(const std::vector<double>& a, const std::vector<double>& b,
                                std::uint64_t seed, std::size_t resamples) {
  check_scores("compare_paired", {&a, &b});
  if (resamples == 0) throw Error("compare_paired: resamples must be positive");
  PairedComparison c;
  c.objects = a.size();
  std::vector<double> difference(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    difference[i] = b[i] - a[i];
    c.wins += a[i] < b[i];
    c.losses += a[i] > b[i];
  }
  const std::size_t decided = c.wins + c.losses;
  if (decided > 0) {
    c.sign_test_p = std::min(1.0, 2.0 * binomial_half_cdf(std::min(c.wins, c.losses), decided));
  }
  const MeanInterval mean = bootstrap_mean(difference, seed, resamples);
  c.mean_difference = mean.mean;
  c.ci_low = mean.low;
  c.ci_high = mean.high;
  return c;
}

FloorComparison compare_with_floor(const std::vector<double>& model,
                                   const std::vector<double>& baseline,
                                   const std::vector<double>& floor) {
  check_scores("compare_with_floor", {&model, &baseline, &floor});
  FloorComparison c;
  c.objects = model.size();
  std::vector<double> excess(model.size());
  for (std::size_t i = 0; i < model.size(); ++i) {
    c.model_wins += model[i] < baseline[i];
    c.floor_wins += floor[i] < baseline[i];
    excess[i] = model[i] - floor[i];
  }
  std::sort(excess.begin(), excess.end());
  const std::size_t middle = excess.size() / 2;
  c.median_excess =
      excess.size() % 2 ? excess[middle] : 0.5 * (excess[middle - 1] + excess[middle]);
  return c;
}

}  // namespace graspecmf::metrics
