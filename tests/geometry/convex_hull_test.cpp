#include "graspecmf/geometry/convex_hull.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "convex_part_checks.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/mass_properties.hpp"

namespace graspecmf::geometry {
namespace {

using namespace graspecmf::geometry::testing;

TEST(ConvexHull, CubeWithInteriorAndFacePoints) {
  std::vector<Vec3> points;
  Rng rng(5);
  for (int i = 0; i < 200; ++i) {
    points.emplace_back(rng.uniform(), rng.uniform(), rng.uniform());
  }
  // Points on the faces (a 5 × 5 lattice on each), the corners among them.
  for (int axis = 0; axis < 3; ++axis) {
    for (const double side : {0.0, 1.0}) {
      for (int i = 0; i <= 4; ++i) {
        for (int j = 0; j <= 4; ++j) {
          Vec3 p;
          p[axis] = side;
          p[(axis + 1) % 3] = i / 4.0;
          p[(axis + 2) % 3] = j / 4.0;
          points.push_back(p);
        }
      }
    }
  }
  const TriangleMesh hull = convex_hull(points);
  expect_convex_part(hull);
  EXPECT_NEAR(mass_properties(hull).volume, 1.0, 1e-12);
  for (const Vec3& p : points) EXPECT_TRUE(in_part(hull, p));
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 c((corner & 1) ? 1.0 : 0.0, (corner & 2) ? 1.0 : 0.0, (corner & 4) ? 1.0 : 0.0);
    EXPECT_NE(std::find(hull.vertices.begin(), hull.vertices.end(), c), hull.vertices.end());
  }
}

TEST(ConvexHull, PointsOnASphereAreAllVertices) {
  std::vector<Vec3> points;
  Rng rng(8);
  for (int i = 0; i < 500; ++i) {
    points.push_back(Vec3(rng.normal(), rng.normal(), rng.normal()).normalized());
  }
  const TriangleMesh hull = convex_hull(points);
  expect_convex_part(hull);
  EXPECT_EQ(hull.vertices.size(), 500u);
  EXPECT_EQ(hull.triangles.size(), 2u * 500u - 4u);
  const double volume = mass_properties(hull).volume;  // inscribed in the unit ball
  EXPECT_LT(volume, 4.0 / 3.0 * M_PI);
  EXPECT_GT(volume, 0.95 * 4.0 / 3.0 * M_PI);
}

TEST(ConvexHull, FlatOrTooFewPointsGiveNothing) {
  EXPECT_TRUE(convex_hull({}).triangles.empty());
  EXPECT_TRUE(convex_hull({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}).triangles.empty());
  std::vector<Vec3> flat;
  for (int i = 0; i < 20; ++i) flat.emplace_back(i % 5, i / 5, 2.0);
  EXPECT_TRUE(convex_hull(flat).triangles.empty());
  std::vector<Vec3> collinear;
  for (int i = 0; i < 20; ++i) collinear.emplace_back(i, 2 * i, 3 * i);
  EXPECT_TRUE(convex_hull(collinear).triangles.empty());
}

TEST(ConvexHull, WithVolumeMatchesTheHullAndItsVolume) {
  std::vector<Vec3> points;
  Rng rng(13);
  for (int i = 0; i < 300; ++i) points.emplace_back(rng.normal(), rng.normal(), rng.normal());
  const ConvexHull hull = convex_hull_with_volume(points);
  const TriangleMesh plain = convex_hull(points);
  EXPECT_EQ(hull.mesh.vertices, plain.vertices);
  EXPECT_EQ(hull.mesh.triangles, plain.triangles);
  EXPECT_NEAR(hull.volume, mass_properties(plain).volume, 1e-12 * hull.volume);
  EXPECT_EQ(convex_hull_with_volume({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}).volume, 0.0);
}

}  // namespace
}  // namespace graspecmf::geometry
