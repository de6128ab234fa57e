// Point-cloud steps of a depth view: voxel downsampling, statistical outlier removal, and fitting
// the table's plane.
#include "graspecmf/camera/view_cloud.hpp"

#include <gtest/gtest.h>

#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/plane_fit.hpp"
#include "test_support.hpp"

namespace graspecmf::camera {
namespace {

using graspecmf::testing::expect_error;

TEST(VoxelDownsample, OnePointPerOccupiedCubeAtItsMean) {
  // A 10 × 10 × 10 lattice of 1 mm pitch in 2 mm cubes: 5³ cubes of 8 points each.
  std::vector<Vec3> points;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      for (int k = 0; k < 10; ++k)
        points.emplace_back(0.0001 + 0.001 * i, 0.0001 + 0.001 * j, 0.0001 + 0.001 * k);
  const std::vector<Vec3> cubes = voxel_downsample(points, 0.002);
  ASSERT_EQ(cubes.size(), 125u);
  EXPECT_NEAR((cubes[0] - Vec3(0.0006, 0.0006, 0.0006)).norm(), 0.0, 1e-12);
  EXPECT_EQ(voxel_downsample(points, 0.0).size(), 1000u);
  expect_error([&] { voxel_downsample(points, -1.0); }, "voxel size");
}

TEST(RemoveOutliers, DropsFlyingPointsAndKeepsTheSurface) {
  Rng rng(3);
  std::vector<Vec3> points;
  for (int i = 0; i < 2000; ++i) points.emplace_back(rng.uniform(0, 0.1), rng.uniform(0, 0.1), 0.5);
  points.emplace_back(0.05, 0.05, 0.45);  // a flying pixel 5 cm off the surface
  points.emplace_back(0.02, 0.08, 0.6);
  const std::vector<Vec3> kept = remove_outliers(points, 16, 2.0);
  EXPECT_EQ(std::count_if(kept.begin(), kept.end(), [](const Vec3& x) { return x.z() != 0.5; }), 0);
  EXPECT_GT(kept.size(), 1900u);  // the surface's own spread removes few
  EXPECT_EQ(remove_outliers(points, 0, 2.0).size(), points.size());
  expect_error([&] { remove_outliers(points, 16, 0.0); }, "ratio");
}

TEST(FitPlane, FindsTheTableAmongClutter) {
  Rng rng(5);
  const Vec3 normal = Vec3(0.1, -0.2, 1.0).normalized();
  const double offset = -0.03;
  std::vector<Vec3> points;
  const Vec3 u = normal.unitOrthogonal(), w = normal.cross(u);
  for (int i = 0; i < 3000; ++i) {
    const Vec3 on = -offset * normal + rng.uniform(-0.3, 0.3) * u + rng.uniform(-0.3, 0.3) * w;
    points.push_back(on + 0.001 * rng.normal() * normal);  // 1 mm of depth noise
  }
  for (int i = 0; i < 1500; ++i) {  // clutter above the table
    points.emplace_back(rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1), rng.uniform(0.02, 0.2));
  }
  const geometry::Plane plane = geometry::fit_plane(points, 0.004, 500, 1);
  const double sign = plane.normal.dot(normal) > 0 ? 1.0 : -1.0;
  EXPECT_LT(std::acos(std::min(1.0, sign * plane.normal.dot(normal))), 0.2 * M_PI / 180);
  EXPECT_NEAR(sign * plane.offset, offset, 3e-4);
  expect_error([&] { geometry::fit_plane(points, 0.004, 5000, 1); }, "no plane holds 5000");
  expect_error([&] { geometry::fit_plane({Vec3::Zero()}, 0.004, 1, 1); }, "at least 3 points");
}

TEST(ParsePlane, NormalisesAndRefusesJunk) {
  const geometry::Plane plane = geometry::parse_plane("0, 0, 2, -0.1", "--table");
  EXPECT_EQ(plane.normal, Vec3(0, 0, 1));
  EXPECT_DOUBLE_EQ(plane.offset, -0.05);
  expect_error([] { geometry::parse_plane("0,0,0,1", "--table"); },
               "--table: \"0,0,0,1\" is not a plane");
  expect_error([] { geometry::parse_plane("0,0,1", "--table"); }, "not a plane");
  expect_error([] { geometry::parse_plane("0,0,1,x", "--table"); }, "not four numbers");
}

}  // namespace
}  // namespace graspecmf::camera
