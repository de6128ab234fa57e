#include "graspecmf/geometry/exact_predicates.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace graspecmf::geometry {

namespace {

int sign_of(double v) {
  return (v > 0.0) - (v < 0.0);
}

// Exact orientation: a floating-point determinant with Shewchuk's error bound, falling back to
// exact expansion arithmetic when the sign is uncertain.

// a + b = sum + error exactly (Knuth).
void two_sum(double a, double b, double& sum, double& error) {
  sum = a + b;
  const double b_virtual = sum - a;
  const double a_virtual = sum - b_virtual;
  error = (a - a_virtual) + (b - b_virtual);
}

// a × b = product + error exactly (barring underflow).
void two_product(double a, double b, double& product, double& error) {
  product = a * b;
  error = std::fma(a, b, -product);
}

// An exact sum of doubles, kept as a non-overlapping expansion ordered by increasing magnitude
// (Shewchuk's Grow-Expansion with zero elimination); its sign is that of the largest part.
class ExactSum {
 public:
  void add(double value) {
    std::size_t kept = 0;
    for (const double part : parts_) {
      double error = 0.0;
      two_sum(value, part, value, error);
      if (error != 0.0) parts_[kept++] = error;
    }
    parts_.resize(kept);
    if (value != 0.0) parts_.push_back(value);
  }
  int sign() const { return parts_.empty() ? 0 : sign_of(parts_.back()); }

 private:
  std::vector<double> parts_;
};

// Exact sign of det[u; v; w] for u = b − a, v = c − a, w = d − a: each difference is an exact
// two-term expansion, and the six products of the Leibniz formula are expanded term by term.
int orientation_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  std::array<std::array<std::array<double, 2>, 3>, 3> m{};  // m[row][column] = {high, low}
  const Vec3* rows[3] = {&b, &c, &d};
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) two_sum((*rows[r])[k], -a[k], m[r][k][0], m[r][k][1]);
  }
  static constexpr int kPermutations[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                              {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  ExactSum sum;
  for (int p = 0; p < 6; ++p) {
    const double sign = p < 3 ? 1.0 : -1.0;
    for (int bits = 0; bits < 8; ++bits) {
      const double x = m[0][kPermutations[p][0]][bits & 1];
      const double y = m[1][kPermutations[p][1]][(bits >> 1) & 1];
      const double z = m[2][kPermutations[p][2]][(bits >> 2) & 1];
      if (x == 0.0 || y == 0.0 || z == 0.0) continue;
      double xy = 0.0;
      double xy_error = 0.0;
      two_product(x, y, xy, xy_error);
      double terms[4];
      two_product(xy, z, terms[0], terms[1]);
      two_product(xy_error, z, terms[2], terms[3]);
      for (const double term : terms) sum.add(sign * term);
    }
  }
  return sum.sign();
}

}  // namespace

int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double ux = b.x() - a.x(), uy = b.y() - a.y(), uz = b.z() - a.z();
  const double vx = c.x() - a.x(), vy = c.y() - a.y(), vz = c.z() - a.z();
  const double wx = d.x() - a.x(), wy = d.y() - a.y(), wz = d.z() - a.z();
  const double vxwy = vx * wy, wxvy = wx * vy;
  const double wxuy = wx * uy, uxwy = ux * wy;
  const double uxvy = ux * vy, vxuy = vx * uy;
  const double det = uz * (vxwy - wxvy) + vz * (wxuy - uxwy) + wz * (uxvy - vxuy);
  const double permanent = (std::abs(vxwy) + std::abs(wxvy)) * std::abs(uz) +
                           (std::abs(wxuy) + std::abs(uxwy)) * std::abs(vz) +
                           (std::abs(uxvy) + std::abs(vxuy)) * std::abs(wz);
  // Shewchuk's bound (7 + 56ε)ε × permanent covers every rounding error of the expression above.
  constexpr double kErrorBound = 7.7715611723761027e-16;
  if (std::abs(det) > kErrorBound * permanent) return sign_of(det);
  if (permanent == 0.0) return 0;  // every product is exactly zero
  return orientation_exact(a, b, c, d);
}

}  // namespace graspecmf::geometry
