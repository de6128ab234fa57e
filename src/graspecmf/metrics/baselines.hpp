#pragma once
// Reference points for the EMD (issue 5): grasps drawn uniformly at random around an object, and
// the shape distance used to find a test object's nearest training object.

#include <cstdint>
#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"
#include "graspecmf/lie/se3.hpp"

namespace graspecmf::metrics {

// n grasps with Haar-uniform rotations and positions uniform in the box grown by margin on every
// side (seeded). Throws Error for a negative or non-finite margin.
std::vector<lie::Pose> random_grasps_in_box(const geometry::BoundingBox& box, double margin,
                                            std::size_t n, std::uint64_t seed);

// Symmetric Chamfer distance: the mean distance from each point of a to its nearest point of b,
// plus the same from b to a (metres). Throws Error if either cloud is empty.
double chamfer_distance(const std::vector<geometry::Vec3>& a, const std::vector<geometry::Vec3>& b);

}  // namespace graspecmf::metrics
