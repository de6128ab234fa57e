#include "graspecmf/geometry/exact_predicates.hpp"

#include <gtest/gtest.h>

#include <cstdint>

#include "graspecmf/core/random.hpp"

namespace graspecmf::geometry {
namespace {

__extension__ typedef __int128 Int128;

TEST(Orientation, SignsOfSimpleConfigurations) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(orientation(a, b, c, Vec3(0.2, 0.2, 1.0)), 1);
  EXPECT_EQ(orientation(a, b, c, Vec3(0.2, 0.2, -1.0)), -1);
  EXPECT_EQ(orientation(a, b, c, Vec3(5.0, -3.0, 0.0)), 0);
  EXPECT_EQ(orientation(a, c, b, Vec3(0.2, 0.2, 1.0)), -1);
}

TEST(Orientation, ExactForNearlyCoplanarPoints) {
  // Integer coordinates up to 2^25: the determinant's products need up to 78 bits, so the
  // floating-point value is rounded, but a 128-bit integer determinant is exact.
  Rng rng(3);
  const auto coordinate = [&] { return static_cast<std::int64_t>(rng.index(1u << 25)); };
  int decided_exactly = 0;
  for (int n = 0; n < 2000; ++n) {
    std::int64_t p[4][3];
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) p[i][k] = coordinate();
    }
    // The fourth point near the plane of the first three: an integer combination, nudged by −1..1.
    const std::int64_t s = static_cast<std::int64_t>(rng.index(7)) - 3;
    const std::int64_t t = static_cast<std::int64_t>(rng.index(7)) - 3;
    for (int k = 0; k < 3; ++k) {
      p[3][k] = p[0][k] + s * (p[1][k] - p[0][k]) + t * (p[2][k] - p[0][k]) +
                static_cast<std::int64_t>(rng.index(3)) - 1;
    }
    Int128 u[3], v[3], w[3];
    for (int k = 0; k < 3; ++k) {
      u[k] = p[1][k] - p[0][k];
      v[k] = p[2][k] - p[0][k];
      w[k] = p[3][k] - p[0][k];
    }
    const Int128 det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                       u[2] * (v[0] * w[1] - v[1] * w[0]);
    const int expected = (det > 0) - (det < 0);
    const auto point = [&](int i) {
      return Vec3(static_cast<double>(p[i][0]), static_cast<double>(p[i][1]),
                  static_cast<double>(p[i][2]));
    };
    ASSERT_EQ(orientation(point(0), point(1), point(2), point(3)), expected) << n;
    decided_exactly += expected == 0 ? 1 : 0;
  }
  EXPECT_GT(decided_exactly, 20);  // exact zeros, which floating point alone cannot certify
}

}  // namespace
}  // namespace graspecmf::geometry
