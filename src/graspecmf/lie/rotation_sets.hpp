#pragma once
// Sets of rotations: seeded Haar-uniform random rotations and the deterministic, quasi-uniform
// super-Fibonacci spiral (Alexa, CVPR 2022) used for fixed test rotations.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "graspecmf/core/random.hpp"
#include "graspecmf/lie/so3.hpp"

namespace graspecmf::lie {

// One rotation drawn from the Haar (uniform) measure on SO(3).
Mat3 random_rotation(Rng& rng);
// n Haar-uniform rotations from a seed.
std::vector<Mat3> random_rotations(std::size_t n, std::uint64_t seed);
// The n-point super-Fibonacci spiral: deterministic, well spread over SO(3), none the identity.
std::vector<Mat3> super_fibonacci_rotations(std::size_t n);

}  // namespace graspecmf::lie
