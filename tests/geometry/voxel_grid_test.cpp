#include "graspecmf/geometry/voxel_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/geometry/point_inside.hpp"
#include "test_meshes.hpp"

namespace graspecmf::geometry {
namespace {

using namespace graspecmf::geometry::testing;

TEST(Voxelize, BoxFillingTheGridOccupiesEveryVoxel) {
  const VoxelGrid grid = voxelize(make_box(Vec3::Zero(), Vec3(1.0, 0.5, 0.25)), 8);
  EXPECT_EQ(grid.dims, (std::array<int, 3>{8, 4, 2}));
  EXPECT_DOUBLE_EQ(grid.voxel_size, 0.125);
  EXPECT_EQ(grid.origin, Vec3::Zero());
  EXPECT_EQ(grid.count(), 64u);
  EXPECT_DOUBLE_EQ(grid.volume(), 0.125);
}

TEST(Voxelize, FacesThroughVoxelCentresAreResolvedConsistently) {
  // Every face of the box passes exactly through a layer of voxel centres, and the face diagonals
  // through the centres of the columns i = j: only a consistent tie rule gives 7 per axis (a
  // centre on a lower x or y face is out, on an upper one in; on the bottom in, on the top out).
  const TriangleMesh box = make_box(Vec3::Constant(0.0625), Vec3::Constant(0.9375));
  const VoxelGrid grid = voxelize(box, Vec3::Zero(), 0.125, {8, 8, 8});
  EXPECT_EQ(grid.count(), 343u);
  EXPECT_DOUBLE_EQ(grid.volume(), 0.875 * 0.875 * 0.875);
  for (int j = 0; j < 8; ++j) {
    for (int i = 0; i < 8; ++i) {
      for (int k = 0; k < 8; ++k) {
        EXPECT_EQ(grid.at(i, j, k), i >= 1 && j >= 1 && k <= 6) << i << " " << j << " " << k;
      }
    }
  }
}

TEST(Voxelize, InwardFacingMeshGivesTheSameVoxels) {
  const TriangleMesh torus = make_torus(1.0, 0.3, 24, 12);
  EXPECT_EQ(voxelize(inverted(torus), 32).occupied, voxelize(torus, 32).occupied);
}

TEST(Voxelize, TorusVolumeAndHole) {
  const TriangleMesh torus = make_torus(1.0, 0.3, 48, 24);
  const VoxelGrid grid = voxelize(torus, 64);
  const double volume = mass_properties(torus).volume;
  EXPECT_NEAR(grid.volume() / volume, 1.0, 0.02);  // measured 1.014
  // Voxel containing the centre of the hole, and one containing the tube's centre line.
  const auto voxel_at = [&](const Vec3& p) {
    const Vec3 index = (p - grid.origin) / grid.voxel_size;
    return grid.at(static_cast<int>(index.x()), static_cast<int>(index.y()),
                   static_cast<int>(index.z()));
  };
  EXPECT_FALSE(voxel_at(Vec3(0.01, 0.01, 0.01)));
  EXPECT_TRUE(voxel_at(Vec3(1.01, 0.01, 0.01)));
  EXPECT_TRUE(voxel_at(Vec3(-0.01, -1.01, 0.01)));
}

TEST(Voxelize, MugAgreesWithTheWindingNumber) {
  const TriangleMesh mug = scaled(read_mesh(kMugPath), kMugScale);
  const VoxelGrid grid = voxelize(mug, 40);
  Rng rng(11);
  int occupied = 0;
  for (int n = 0; n < 1500; ++n) {
    const int i = static_cast<int>(rng.index(static_cast<std::size_t>(grid.dims[0])));
    const int j = static_cast<int>(rng.index(static_cast<std::size_t>(grid.dims[1])));
    const int k = static_cast<int>(rng.index(static_cast<std::size_t>(grid.dims[2])));
    EXPECT_EQ(grid.at(i, j, k), is_inside(mug, grid.center(i, j, k))) << i << " " << j << " " << k;
    occupied += grid.at(i, j, k) ? 1 : 0;
  }
  EXPECT_GT(occupied, 50);  // the mug fills about 9 % of its bounding box
}

TEST(Voxelize, MugVolumeConverges) {
  const TriangleMesh mug = scaled(read_mesh(kMugPath), kMugScale);
  const double volume = mass_properties(mug).volume;
  // The 4 mm base is parallel to the grid, so coarse grids round it by up to half a voxel.
  EXPECT_NEAR(voxelize(mug, 64).volume() / volume, 1.0, 0.05);
  EXPECT_NEAR(voxelize(mug, 128).volume() / volume, 1.0, 0.01);
}

TEST(ColumnSpans, ExactIntervalsThroughABox) {
  const TriangleMesh box = make_box(Vec3(0.0, 0.0, -0.3), Vec3(1.0, 1.0, 0.7));
  const ColumnSpans lines = column_spans(box, 0.25, 0.25, 0.5, 3, 3);
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      const bool through = i < 2 && j < 2;  // lines at 0.25 and 0.75 pass through the box
      EXPECT_DOUBLE_EQ(lines.inside_length(i, j, -1.0, 1.0), through ? 1.0 : 0.0);
      EXPECT_DOUBLE_EQ(lines.inside_length(i, j, 0.2, 5.0), through ? 0.5 : 0.0);
      EXPECT_EQ(lines.inside(i, j, -0.3), through);  // entering height: inside
      EXPECT_FALSE(lines.inside(i, j, 0.7));         // leaving height: outside
      EXPECT_EQ(lines.inside(i, j, 0.0), through);
    }
  }
}

TEST(ColumnSpans, TorusLineCrossesTheTubeTwice) {
  const TriangleMesh torus = make_torus(1.0, 0.3, 48, 24);
  const ColumnSpans lines = column_spans(torus, -1.0, 0.0, 1.0, 3, 1);
  // Lines at x = −1, 0 and 1 on y = 0: the outer two pass through the tube's centre, the middle one
  // through the hole.
  ASSERT_EQ(lines.first.size(), 4u);
  EXPECT_EQ(lines.first[1] - lines.first[0], 1u);
  EXPECT_EQ(lines.first[2] - lines.first[1], 0u);
  EXPECT_EQ(lines.first[3] - lines.first[2], 1u);
  EXPECT_NEAR(lines.inside_length(2, 0, -1.0, 1.0), 0.6, 1e-12);  // a vertex ring lies on x = 1
}

TEST(ColumnSpans, LinesThroughEdgesCountEachCrossingOnce) {
  // A line through the rounded midpoint of an edge is on it up to rounding, so the two triangles
  // sharing the edge must see the same side; otherwise the crossing is lost or doubled and the
  // spans change completely, not by the line's tiny shift.
  const lie::Pose pose{lie::so3_exp(Eigen::Vector3d(0.4, 0.7, -0.2)), Eigen::Vector3d::Zero()};
  const TriangleMesh torus = transformed(make_torus(1.0, 0.3, 48, 24), pose);
  Rng rng(4);
  for (int n = 0; n < 400; ++n) {
    const Triangle& tri = torus.triangles[rng.index(torus.triangles.size())];
    const int k = static_cast<int>(rng.index(3));
    const Vec3 mid = 0.5 * (torus.vertices[tri[k]] + torus.vertices[tri[(k + 1) % 3]]);
    const double on_edge =
        column_spans(torus, mid.x(), mid.y(), 1.0, 1, 1).inside_length(0, 0, -1.0, 1.0);
    const double beside = column_spans(torus, mid.x() + 1e-9, mid.y() + 2e-9, 1.0, 1, 1)
                              .inside_length(0, 0, -1.0, 1.0);
    EXPECT_NEAR(on_edge, beside, 1e-4) << n;
  }
}

TEST(Voxelize, RejectsOpenMeshesAndBadGrids) {
  TriangleMesh open = make_unit_cube();
  open.triangles.pop_back();
  EXPECT_THROW(voxelize(open, 16), Error);
  EXPECT_THROW(column_spans(open, 0.0, 0.0, 0.1, 4, 4), Error);
  const TriangleMesh cube = make_unit_cube();
  EXPECT_THROW(voxelize(cube, 0), Error);
  EXPECT_THROW(voxelize(cube, 1025), Error);
  EXPECT_THROW(voxelize(cube, Vec3::Zero(), 0.0, {4, 4, 4}), Error);
  EXPECT_THROW(voxelize(cube, Vec3::Zero(), std::nan(""), {4, 4, 4}), Error);
  EXPECT_THROW(voxelize(cube, Vec3::Zero(), 0.25, {4, 0, 4}), Error);
  EXPECT_THROW(
      voxelize(cube, Vec3(std::numeric_limits<double>::infinity(), 0.0, 0.0), 0.25, {4, 4, 4}),
      Error);
  EXPECT_THROW(voxelize(cube, Vec3::Zero(), 1e-4, {1024, 1024, 1025}), Error);
}

}  // namespace
}  // namespace graspecmf::geometry
