#include "graspecmf/lie/rotation_sets.hpp"

#include <cmath>

namespace graspecmf::lie {

namespace {

// The rotation of the unit quaternion w + xi + yj + zk.
Mat3 quaternion_matrix(double w, double x, double y, double z) {
  Mat3 R;
  R << 1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y),  //
      2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x),   //
      2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y);
  return R;
}

}  // namespace

Mat3 random_rotation(Rng& rng) {
  // A normalised isotropic Gaussian in R⁴ is uniform on S³, and S³ → SO(3) pushes that to Haar.
  for (;;) {
    const double w = rng.normal();
    const double x = rng.normal();
    const double y = rng.normal();
    const double z = rng.normal();
    const double norm = std::sqrt(w * w + x * x + y * y + z * z);
    if (norm < 1e-6) continue;  // probability ~1e-25; avoids dividing by ~0
    return quaternion_matrix(w / norm, x / norm, y / norm, z / norm);
  }
}

std::vector<Mat3> random_rotations(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Mat3> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(random_rotation(rng));
  return out;
}

std::vector<Mat3> super_fibonacci_rotations(std::size_t n) {
  // Alexa, "Super-Fibonacci Spirals" (CVPR 2022): two Fibonacci-like angle sequences with the
  // incommensurable periods √2 and ψ (the real root of ψ⁴ = ψ + 4) on the two circles of a Hopf-
  // like split of S³, with radii chosen so the points are equal-area in the volume of S³.
  constexpr double kPhi = 1.4142135623730950488;  // √2
  constexpr double kPsi = 1.533751168755204288118041;
  constexpr double two_pi = 2.0 * 3.14159265358979323846;
  const double dn = static_cast<double>(n);
  std::vector<Mat3> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) + 0.5;
    const double r = std::sqrt(s / dn);
    const double big_r = std::sqrt(1.0 - s / dn);
    const double alpha = two_pi * s / kPhi;
    const double beta = two_pi * s / kPsi;
    // (x, y, z, w) = (r sin α, r cos α, R sin β, R cos β); |q| = 1 by construction.
    out.push_back(quaternion_matrix(big_r * std::cos(beta), r * std::sin(alpha),
                                    r * std::cos(alpha), big_r * std::sin(beta)));
  }
  return out;
}

}  // namespace graspecmf::lie
