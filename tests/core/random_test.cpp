#include "graspecmf/core/random.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "graspecmf/core/error.hpp"

namespace graspecmf {
namespace {

TEST(Rng, SameSeedSameStream) {
  Rng a(42), b(42), c(43);
  bool differs = false;
  for (int i = 0; i < 100; ++i) {
    const double x = a.uniform();
    EXPECT_EQ(x, b.uniform());
    differs |= x != c.uniform();
  }
  EXPECT_TRUE(differs);
}

TEST(Rng, UniformMomentsAndRange) {
  Rng rng(7);
  const int n = 200000;
  double sum = 0, sum_sq = 0;
  for (int i = 0; i < n; ++i) {
    const double x = rng.uniform();
    ASSERT_GE(x, 0.0);
    ASSERT_LT(x, 1.0);
    sum += x;
    sum_sq += x * x;
  }
  // Mean 1/2 (sd of the mean 0.29/sqrt(n)), second moment 1/3.
  EXPECT_NEAR(sum / n, 0.5, 4 * 0.2887 / std::sqrt(n));
  EXPECT_NEAR(sum_sq / n, 1.0 / 3.0, 4 * 0.298 / std::sqrt(n));
}

TEST(Rng, NormalMoments) {
  Rng rng(11);
  const int n = 200000;
  double sum = 0, sum_sq = 0, sum_4 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = rng.normal();
    sum += x;
    sum_sq += x * x;
    sum_4 += x * x * x * x;
  }
  EXPECT_NEAR(sum / n, 0.0, 4 / std::sqrt(n));
  EXPECT_NEAR(sum_sq / n, 1.0, 4 * std::sqrt(2.0 / n));
  EXPECT_NEAR(sum_4 / n, 3.0, 4 * std::sqrt(96.0 / n));
}

TEST(Rng, IndexIsUniformOverSmallRange) {
  Rng rng(3);
  std::vector<int> counts(7, 0);
  const int n = 70000;
  for (int i = 0; i < n; ++i) ++counts[rng.index(7)];
  for (const int count : counts) EXPECT_NEAR(count, n / 7.0, 5 * std::sqrt(n / 7.0));
}

TEST(Rng, RestoredStateContinuesTheSameStream) {
  Rng rng(11);
  for (int i = 0; i < 5; ++i) rng.normal();  // leaves a spare normal pending
  const std::string saved = rng.state();
  std::vector<double> expected;
  for (int i = 0; i < 9; ++i) expected.push_back(i % 2 ? rng.normal() : rng.uniform());
  Rng other(99);
  other.restore(saved);
  for (int i = 0; i < 9; ++i) {
    EXPECT_EQ(i % 2 ? other.normal() : other.uniform(), expected[static_cast<std::size_t>(i)]);
  }
  EXPECT_THROW(other.restore("not a state"), Error);
}

}  // namespace
}  // namespace graspecmf
