#include "graspecmf/geometry/convex_decomposition.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "convex_part_checks.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/point_inside.hpp"
#include "mug_fixture.hpp"
#include "test_meshes.hpp"

namespace graspecmf::geometry {
namespace {

using namespace graspecmf::geometry::testing;

bool in_any_part(const std::vector<TriangleMesh>& parts, const Vec3& q) {
  return std::any_of(parts.begin(), parts.end(),
                     [&](const TriangleMesh& part) { return in_part(part, q); });
}

double total_volume(const std::vector<TriangleMesh>& parts) {
  double sum = 0.0;
  for (const TriangleMesh& part : parts) sum += mass_properties(part).volume;
  return sum;
}

// Prism over the L-shaped polygon [0,2]² minus [1,2]×[1,2], z in [0,1]: two unit-square boxes
// side by side plus one on top of the first, volume 3.
TriangleMesh make_l_prism() {
  const double outline[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  TriangleMesh mesh;
  for (const double z : {0.0, 1.0}) {
    for (const auto& p : outline) mesh.vertices.emplace_back(p[0], p[1], z);
  }
  // The L split into the squares (0,1,2,3) ∪ ... as a fan from vertex 3 (the reflex corner).
  mesh.triangles = {{3, 2, 1}, {3, 1, 0}, {3, 0, 5},  {3, 5, 4},
                    {9, 7, 8}, {9, 6, 7}, {9, 11, 6}, {9, 10, 11}};
  for (std::uint32_t i = 0; i < 6; ++i) {
    const std::uint32_t j = (i + 1) % 6;
    mesh.triangles.push_back({i, j, j + 6});
    mesh.triangles.push_back({i, j + 6, i + 6});
  }
  return mesh;
}

// The mug's body axis (vertical line) from its bounding box: centred in x, and one body radius
// (half the x extent) inside the +y side, the handle being on the −y side.
Vec3 mug_axis_point(double z) {
  const BoundingBox box = bounding_box(metric_mug());
  return Vec3(box.center().x(), box.max.y() - 0.5 * box.extent().x(), z);
}

TEST(ConvexDecomposition, ConvexMeshesStayWhole) {
  const TriangleMesh box = make_box(Vec3(-0.1, 0.2, 0.0), Vec3(0.3, 0.25, 0.9));
  const std::vector<TriangleMesh> parts = convex_decomposition(box);
  ASSERT_EQ(parts.size(), 1u);
  expect_convex_part(parts[0]);
  EXPECT_NEAR(mass_properties(parts[0]).volume, mass_properties(box).volume, 1e-15);

  const lie::Pose pose{lie::so3_exp(Eigen::Vector3d(0.3, -0.5, 0.8)), Eigen::Vector3d(1, 2, 3)};
  const TriangleMesh tilted = transformed(box, pose);
  const std::vector<TriangleMesh> tilted_parts = convex_decomposition(tilted);
  ASSERT_EQ(tilted_parts.size(), 1u);
  EXPECT_NEAR(mass_properties(tilted_parts[0]).volume, mass_properties(tilted).volume, 1e-15);
}

TEST(ConvexDecomposition, LShapeSplitsIntoItsTwoBoxes) {
  // The cells' solid volumes are exact, so once the L is cut at its reflex corner neither half has
  // any excess and the decomposition stops at two exact boxes (its faces lie on lattice planes,
  // which exercises every tie rule).
  const std::vector<TriangleMesh> parts = convex_decomposition(make_l_prism(), {8, 64, 0.002, 4});
  ASSERT_EQ(parts.size(), 2u);
  for (const TriangleMesh& part : parts) expect_convex_part(part);
  EXPECT_NEAR(total_volume(parts), 3.0, 1e-12);
  EXPECT_FALSE(in_any_part(parts, Vec3(1.5, 1.5, 0.5)));
}

TEST(ConvexDecomposition, TorusKeepsItsHoleOpen) {
  const TriangleMesh torus = make_torus(1.0, 0.3, 48, 24);
  const std::vector<TriangleMesh> parts = convex_decomposition(torus);
  EXPECT_LE(parts.size(), 64u);
  for (const TriangleMesh& part : parts) expect_convex_part(part);
  EXPECT_LT(total_volume(parts) / mass_properties(torus).volume, 1.1);
  for (const double z : {-0.2, 0.0, 0.2}) {
    EXPECT_FALSE(in_any_part(parts, Vec3(0.0, 0.0, z)));
    EXPECT_FALSE(in_any_part(parts, Vec3(0.45, 0.3, z)));
  }
}

TEST(ConvexDecomposition, MugPartsAreClosedConvexAndFew) {
  const std::vector<TriangleMesh>& parts = mug_parts();
  EXPECT_GE(parts.size(), 8u);
  EXPECT_LE(parts.size(), 64u);
  for (const TriangleMesh& part : parts) expect_convex_part(part);
}

TEST(ConvexDecomposition, MugVolumeWithinFifteenPercent) {
  const double mesh_volume = mass_properties(metric_mug()).volume;
  EXPECT_NEAR(mesh_volume, 8.725e-05, 1e-8);
  const double ratio = total_volume(mug_parts()) / mesh_volume;
  EXPECT_GE(ratio, 1.0);  // the parts cover the solid
  EXPECT_LE(ratio, 1.15);
  EXPECT_LE(ratio, 1.09);  // measured 1.074 with the default options
}

TEST(ConvexDecomposition, MugCavityIsEmpty) {
  // Base top: where a ray down the axis from above the rim first meets the mug.
  const BoundingBox box = bounding_box(metric_mug());
  const std::vector<double> down =
      ray_hits(metric_mug(), mug_axis_point(box.max.z() + 0.01), -Vec3::UnitZ());
  ASSERT_FALSE(down.empty());
  const double base_top = box.max.z() + 0.01 - down.front();
  EXPECT_NEAR(base_top - box.min.z(), 0.004, 0.002);  // the base is about 4 mm thick
  // Inner radius at mid-height: where a ray from the axis towards +y meets the inner wall.
  const double mid = 0.5 * (base_top + box.max.z());
  const std::vector<double> side = ray_hits(metric_mug(), mug_axis_point(mid), Vec3::UnitY());
  ASSERT_EQ(side.size(), 2u);
  const double inner_radius = side.front();
  for (const double f : {0.1, 0.3, 0.5, 0.7, 0.9, 1.0}) {
    const Vec3 q = mug_axis_point(base_top + f * (box.max.z() - base_top));
    ASSERT_FALSE(is_inside(metric_mug(), q));
    EXPECT_FALSE(in_any_part(mug_parts(), q)) << "axis at " << f << " of the cavity depth";
  }
  for (int k = 0; k < 8; ++k) {
    const double angle = k * M_PI / 4.0;
    const Vec3 q =
        mug_axis_point(mid) + 0.7 * inner_radius * Vec3(std::cos(angle), std::sin(angle), 0.0);
    ASSERT_FALSE(is_inside(metric_mug(), q));
    EXPECT_FALSE(in_any_part(mug_parts(), q)) << "off the axis at angle " << angle;
  }
}

TEST(ConvexDecomposition, MugHandleHoleIsEmpty) {
  // At each height where a ray from the axis towards −y crosses the wall (2 hits) and then the
  // handle (2 more), the midpoint of the gap between them lies in the handle's hole.
  const BoundingBox box = bounding_box(metric_mug());
  int holes = 0;
  for (double z = box.min.z(); z < box.max.z(); z += 0.002) {
    const Vec3 origin = mug_axis_point(z);
    const std::vector<double> hits = ray_hits(metric_mug(), origin, -Vec3::UnitY());
    if (hits.size() != 4 || hits[2] - hits[1] < 0.004) continue;
    const Vec3 hole = origin - 0.5 * (hits[1] + hits[2]) * Vec3::UnitY();
    ASSERT_FALSE(is_inside(metric_mug(), hole));
    EXPECT_FALSE(in_any_part(mug_parts(), hole)) << "hole at z = " << z;
    ++holes;
  }
  EXPECT_GE(holes, 10);
}

TEST(ConvexDecomposition, MugSolidIsCovered) {
  const BoundingBox box = bounding_box(metric_mug());
  Rng rng(21);
  int samples = 0;
  int covered = 0;
  while (samples < 400) {
    Vec3 q;
    for (int k = 0; k < 3; ++k) q[k] = rng.uniform(box.min[k], box.max[k]);
    if (!is_inside(metric_mug(), q)) continue;
    ++samples;
    covered += in_any_part(mug_parts(), q) ? 1 : 0;
  }
  EXPECT_EQ(covered, samples);  // cells tile space and each part holds its cells' solid exactly
}

TEST(ConvexDecomposition, IsDeterministic) {
  const std::vector<TriangleMesh> again = convex_decomposition(metric_mug());
  ASSERT_EQ(again.size(), mug_parts().size());
  for (std::size_t i = 0; i < again.size(); ++i) {
    EXPECT_EQ(again[i].vertices, mug_parts()[i].vertices);
    EXPECT_EQ(again[i].triangles, mug_parts()[i].triangles);
  }
}

TEST(ConvexDecomposition, RespectsTheBudget) {
  for (const int budget : {1, 6}) {
    DecompositionOptions options;
    options.max_parts = budget;
    const std::vector<TriangleMesh> parts = convex_decomposition(metric_mug(), options);
    EXPECT_GE(parts.size(), 1u);
    EXPECT_LE(parts.size(), static_cast<std::size_t>(budget));
    EXPECT_GE(total_volume(parts), mass_properties(metric_mug()).volume);
  }
}

TEST(ConvexDecomposition, RejectsBadInput) {
  TriangleMesh open = make_unit_cube();
  open.triangles.pop_back();
  EXPECT_THROW(convex_decomposition(open), Error);
  const TriangleMesh cube = make_unit_cube();
  EXPECT_THROW(convex_decomposition(cube, {3, 64, 0.002, 4}), Error);
  EXPECT_THROW(convex_decomposition(cube, {257, 64, 0.002, 4}), Error);
  EXPECT_THROW(convex_decomposition(cube, {64, 0, 0.002, 4}), Error);
  EXPECT_THROW(convex_decomposition(cube, {64, 64, -0.1, 4}), Error);
  EXPECT_THROW(convex_decomposition(cube, {64, 64, std::nan(""), 4}), Error);
  EXPECT_THROW(convex_decomposition(cube, {64, 64, 0.002, 0}), Error);
}

}  // namespace
}  // namespace graspecmf::geometry
