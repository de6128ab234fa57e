#pragma once
// Planes in 3-D: parsing one from text, and finding the plane most points lie on (RANSAC, refit by
// least squares), e.g. the table under an object in a depth image.

#include <cstdint>
#include <string>
#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

// The points x with normal · x + offset = 0; normal is a unit vector, and points with a positive
// signed distance lie on the side it points to.
struct Plane {
  Vec3 normal = Vec3::UnitZ();
  double offset = 0.0;
  double signed_distance(const Vec3& x) const { return normal.dot(x) + offset; }
};

// The plane "a,b,c,d" (a x + b y + c z + d = 0), scaled so that (a, b, c) is a unit vector. Throws
// Error naming `what` unless there are four finite numbers with (a, b, c) not zero.
Plane parse_plane(const std::string& text, const std::string& what);

// The plane with the most points within inlier_distance of it among `trials` planes through
// seeded random triples, refit by least squares to those points (its normal's sign is arbitrary).
// Throws Error if there are fewer than 3 points, inlier_distance is not positive and finite, or
// no plane holds at least min_inliers points.
Plane fit_plane(const std::vector<Vec3>& points, double inlier_distance, std::size_t min_inliers,
                std::uint64_t seed, int trials = 400);

}  // namespace graspecmf::geometry
