#pragma once
// From a depth image to a point cloud: back-projection of the pixels with a reading, voxel
// downsampling, and statistical outlier removal (flying pixels at depth edges, speckle).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "graspecmf/camera/depth_image.hpp"
#include "graspecmf/camera/intrinsics.hpp"

namespace graspecmf::camera {

using Vec3 = Eigen::Vector3d;

// Which pixels back_project takes, given a mask.
enum class Pixels {
  all,         // every pixel with a reading (the mask is ignored)
  object,      // the mask's non-zero pixels
  background,  // the mask's zero pixels
};

// Camera-frame points (metres) of the chosen pixels with a reading (depth > 0), row by row.
// Throws Error if the intrinsics give a size other than the image's, or the mask's size differs.
std::vector<Vec3> back_project(const DepthImage& depth, const Intrinsics& intrinsics,
                               const std::vector<std::uint8_t>& mask = {},
                               Pixels pixels = Pixels::all);

// One point per occupied cube of side `voxel` (the mean of its points), cubes in the order their
// first point comes; voxel = 0 returns the points unchanged. Throws Error if voxel is negative or
// not finite.
std::vector<Vec3> voxel_downsample(const std::vector<Vec3>& points, double voxel);

// The points whose mean distance to their `neighbours` nearest points is at most the mean of that
// distance over all points plus std_ratio standard deviations; order kept. neighbours = 0, or
// fewer points than neighbours + 1, returns them unchanged. Throws Error if std_ratio is not
// positive and finite or neighbours is negative.
std::vector<Vec3> remove_outliers(const std::vector<Vec3>& points, int neighbours,
                                  double std_ratio);

}  // namespace graspecmf::camera
