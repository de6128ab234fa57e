#include "graspecmf/metrics/paired_comparison.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "graspecmf/core/error.hpp"

namespace graspecmf::metrics {
namespace {

// Scores where a wins `wins` objects by 0.1 and loses `losses` by 0.05.
std::pair<std::vector<double>, std::vector<double>> scores(int wins, int losses) {
  std::vector<double> a, b;
  for (int i = 0; i < wins; ++i) {
    a.push_back(0.3);
    b.push_back(0.4);
  }
  for (int i = 0; i < losses; ++i) {
    a.push_back(0.35);
    b.push_back(0.3);
  }
  return {a, b};
}

TEST(PairedComparison, SignTestMatchesTheBinomialDistribution) {
  // Two-sided exact values: 2·P(X ≤ k) for X ~ Binomial(m, 1/2).
  const auto [a18, b18] = scores(18, 12);
  EXPECT_NEAR(compare_paired(a18, b18, 1).sign_test_p, 0.361594608053565, 1e-12);
  const auto [a24, b24] = scores(24, 6);
  EXPECT_NEAR(compare_paired(a24, b24, 1).sign_test_p, 0.001430906355381012, 1e-12);
  const auto [a5, b5] = scores(5, 0);
  EXPECT_NEAR(compare_paired(a5, b5, 1).sign_test_p, 0.0625, 1e-12);
  const auto [a3, b3] = scores(3, 3);
  EXPECT_EQ(compare_paired(a3, b3, 1).sign_test_p, 1.0);  // capped at 1
}

TEST(PairedComparison, CountsWinsLossesAndTies) {
  const PairedComparison c = compare_paired({0.1, 0.5, 0.3, 0.2}, {0.2, 0.4, 0.3, 0.2}, 3);
  EXPECT_EQ(c.objects, 4u);
  EXPECT_EQ(c.wins, 1u);
  EXPECT_EQ(c.losses, 1u);
  EXPECT_EQ(c.sign_test_p, 1.0);
  EXPECT_NEAR(c.mean_difference, 0.0, 1e-15);
  const PairedComparison ties = compare_paired({0.1, 0.2}, {0.1, 0.2}, 3);
  EXPECT_EQ(ties.wins + ties.losses, 0u);
  EXPECT_EQ(ties.sign_test_p, 1.0);
  EXPECT_EQ(ties.ci_low, 0.0);
  EXPECT_EQ(ties.ci_high, 0.0);
}

TEST(PairedComparison, BootstrapIntervalIsSeededAndBracketsTheMean) {
  const auto [a, b] = scores(18, 12);
  const PairedComparison c = compare_paired(a, b, 7);
  EXPECT_NEAR(c.mean_difference, (18 * 0.1 - 12 * 0.05) / 30, 1e-12);
  EXPECT_LT(c.ci_low, c.mean_difference);
  EXPECT_GT(c.ci_high, c.mean_difference);
  // Each resampled mean is 0.1 − 0.15·(share of losses), so the interval ends on that grid.
  const double losses_low = (0.1 - c.ci_high) / 0.15 * 30,
               losses_high = (0.1 - c.ci_low) / 0.15 * 30;
  EXPECT_NEAR(losses_low, std::round(losses_low), 1e-9);
  EXPECT_NEAR(losses_high, std::round(losses_high), 1e-9);
  EXPECT_LT(losses_low, 12.0);
  EXPECT_GT(losses_high, 12.0);
  const PairedComparison again = compare_paired(a, b, 7);
  EXPECT_EQ(again.ci_low, c.ci_low);
  EXPECT_EQ(again.ci_high, c.ci_high);
  // A constant difference has a zero-width interval at that difference.
  const PairedComparison shift = compare_paired({0.1, 0.2, 0.3}, {0.15, 0.25, 0.35}, 7);
  EXPECT_NEAR(shift.ci_low, 0.05, 1e-12);
  EXPECT_NEAR(shift.ci_high, 0.05, 1e-12);
  EXPECT_EQ(shift.wins, 3u);
}

TEST(BootstrapMean, IntervalOfAShareMatchesTheNormalApproximation) {
  // 60 objects, 20 of them 1: mean 1/3, standard error sqrt(p (1 − p) / n) ≈ 0.0609.
  std::vector<double> values(60, 0.0);
  for (std::size_t i = 0; i < 20; ++i) values[3 * i] = 1.0;
  const MeanInterval m = bootstrap_mean(values, 5);
  EXPECT_NEAR(m.mean, 1.0 / 3, 1e-15);
  const double half_width = 1.96 * std::sqrt((1.0 / 3) * (2.0 / 3) / 60);
  EXPECT_NEAR(m.low, 1.0 / 3 - half_width, 0.02);
  EXPECT_NEAR(m.high, 1.0 / 3 + half_width, 0.02);
  EXPECT_EQ(bootstrap_mean(values, 5).low, m.low);  // seeded
  // The paired comparison's interval is the bootstrap interval of the differences.
  const auto [a, b] = scores(18, 12);
  std::vector<double> difference(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) difference[i] = b[i] - a[i];
  EXPECT_EQ(compare_paired(a, b, 9).ci_low, bootstrap_mean(difference, 9).low);
  EXPECT_THROW(bootstrap_mean({}, 1), Error);
  EXPECT_THROW(bootstrap_mean({0.5}, 1, 0), Error);
}

TEST(PairedComparison, RejectsBadInput) {
  EXPECT_THROW(compare_paired({0.1}, {0.1, 0.2}, 1), Error);
  EXPECT_THROW(compare_paired({}, {}, 1), Error);
  EXPECT_THROW(compare_paired({0.1}, {std::numeric_limits<double>::quiet_NaN()}, 1), Error);
  EXPECT_THROW(compare_paired({0.1}, {0.2}, 1, 0), Error);
}

TEST(FloorComparison, CountsWinsOfTheModelAndOfThePerfectSampler) {
  // Object 0: both below the baseline; 1: only the floor; 2: neither (the baseline sits below the
  // floor, as retrieval of a near-duplicate can); 3: only the floor, and a tie for the model.
  const FloorComparison c = compare_with_floor({0.30, 0.50, 0.40, 0.35}, {0.40, 0.45, 0.22, 0.35},
                                               {0.25, 0.20, 0.24, 0.30});
  EXPECT_EQ(c.objects, 4u);
  EXPECT_EQ(c.model_wins, 1u);
  EXPECT_EQ(c.floor_wins, 3u);
  // Excesses 0.05, 0.30, 0.16, 0.05: the median of an even count is the mean of the middle two.
  EXPECT_NEAR(c.median_excess, 0.105, 1e-12);
  EXPECT_NEAR(compare_with_floor({0.3, 0.6, 0.2}, {1, 1, 1}, {0.1, 0.1, 0.1}).median_excess, 0.2,
              1e-12);
}

TEST(FloorComparison, RejectsBadInput) {
  EXPECT_THROW(compare_with_floor({0.1}, {0.1}, {0.1, 0.2}), Error);
  EXPECT_THROW(compare_with_floor({}, {}, {}), Error);
  EXPECT_THROW(compare_with_floor({0.1}, {0.2}, {std::numeric_limits<double>::infinity()}), Error);
}

}  // namespace
}  // namespace graspecmf::metrics
