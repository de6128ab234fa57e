#include "graspecmf/geometry/convex_decomposition.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"
#include "graspecmf/geometry/point_inside.hpp"
#include "test_meshes.hpp"

namespace graspecmf::geometry {
namespace {

using namespace graspecmf::geometry::testing;

__extension__ typedef __int128 Int128;

// True if q lies on the inner side of (or on) every face plane of the convex part.
bool in_part(const TriangleMesh& part, const Vec3& q) {
  return std::all_of(part.triangles.begin(), part.triangles.end(), [&](const Triangle& t) {
    return orientation(part.vertices[t[0]], part.vertices[t[1]], part.vertices[t[2]], q) <= 0;
  });
}

bool in_any_part(const std::vector<TriangleMesh>& parts, const Vec3& q) {
  return std::any_of(parts.begin(), parts.end(),
                     [&](const TriangleMesh& part) { return in_part(part, q); });
}

double total_volume(const std::vector<TriangleMesh>& parts) {
  double sum = 0.0;
  for (const TriangleMesh& part : parts) sum += mass_properties(part).volume;
  return sum;
}

// Closed, consistently outward, positive volume, and every vertex on or below every face plane.
void expect_convex_part(const TriangleMesh& part) {
  const MeshTopology topology = analyze_topology(part);
  EXPECT_TRUE(topology.watertight);
  EXPECT_TRUE(topology.consistently_oriented);
  EXPECT_EQ(topology.genus, 0);
  EXPECT_GT(mass_properties(part).volume, 0.0);
  for (const Vec3& v : part.vertices) EXPECT_TRUE(in_part(part, v));
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

const TriangleMesh& metric_mug() {
  static const TriangleMesh mug = scaled(read_mesh(kMugPath), kMugScale);
  return mug;
}

const std::vector<TriangleMesh>& mug_parts() {
  static const std::vector<TriangleMesh> parts = convex_decomposition(metric_mug());
  return parts;
}

// Sorted distances along the ray at which it crosses the mesh.
std::vector<double> ray_hits(const TriangleMesh& mesh, const Vec3& origin, const Vec3& dir) {
  std::vector<double> hits;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (const auto hit = ray_hit(mesh, t, origin, dir)) hits.push_back(*hit);
  }
  std::sort(hits.begin(), hits.end());
  return hits;
}

// The mug's body axis (vertical line) from its bounding box: centred in x, and one body radius
// (half the x extent) inside the +y side, the handle being on the −y side.
Vec3 mug_axis_point(double z) {
  const BoundingBox box = bounding_box(metric_mug());
  return Vec3(box.center().x(), box.max.y() - 0.5 * box.extent().x(), z);
}

TEST(Orientation, SignsOfSimpleConfigurations) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(orientation(a, b, c, Vec3(0.2, 0.2, 1.0)), 1);
  EXPECT_EQ(orientation(a, b, c, Vec3(0.2, 0.2, -1.0)), -1);
  EXPECT_EQ(orientation(a, b, c, Vec3(5.0, -3.0, 0.0)), 0);
  EXPECT_EQ(orientation(a, c, b, Vec3(0.2, 0.2, 1.0)), -1);
}

TEST(Orientation, ExactForNearlyCoplanarPoints) {
  // Integer coordinates up to 2^25: the determinant's products need up to 78 bits, so the
  // floating-point value is rounded, but a 128-bit integer determinant is exact.
  Rng rng(3);
  const auto coordinate = [&] { return static_cast<std::int64_t>(rng.index(1u << 25)); };
  int decided_exactly = 0;
  for (int n = 0; n < 2000; ++n) {
    std::int64_t p[4][3];
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) p[i][k] = coordinate();
    }
    // The fourth point near the plane of the first three: an integer combination, nudged by −1..1.
    const std::int64_t s = static_cast<std::int64_t>(rng.index(7)) - 3;
    const std::int64_t t = static_cast<std::int64_t>(rng.index(7)) - 3;
    for (int k = 0; k < 3; ++k) {
      p[3][k] = p[0][k] + s * (p[1][k] - p[0][k]) + t * (p[2][k] - p[0][k]) +
                static_cast<std::int64_t>(rng.index(3)) - 1;
    }
    Int128 u[3], v[3], w[3];
    for (int k = 0; k < 3; ++k) {
      u[k] = p[1][k] - p[0][k];
      v[k] = p[2][k] - p[0][k];
      w[k] = p[3][k] - p[0][k];
    }
    const Int128 det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                       u[2] * (v[0] * w[1] - v[1] * w[0]);
    const int expected = (det > 0) - (det < 0);
    const auto point = [&](int i) {
      return Vec3(static_cast<double>(p[i][0]), static_cast<double>(p[i][1]),
                  static_cast<double>(p[i][2]));
    };
    ASSERT_EQ(orientation(point(0), point(1), point(2), point(3)), expected) << n;
    decided_exactly += expected == 0 ? 1 : 0;
  }
  EXPECT_GT(decided_exactly, 20);  // exact zeros, which floating point alone cannot certify
}

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

void expect_same_parts(const std::vector<TriangleMesh>& a, const std::vector<TriangleMesh>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].vertices, b[i].vertices);
    EXPECT_EQ(a[i].triangles, b[i].triangles);
  }
}

TEST(DecompositionCache, WritesOnceThenReads) {
  ScratchDir dir;
  const fs::path cache = dir / "cache" / "nested";  // created on demand
  const DecompositionOptions options;
  const fs::path file = decomposition_cache_file(metric_mug(), options, cache);
  EXPECT_EQ(file.parent_path(), cache);
  EXPECT_FALSE(fs::exists(file));
  expect_same_parts(cached_convex_decomposition(metric_mug(), options, cache), mug_parts());
  ASSERT_TRUE(fs::exists(file));
  const std::string bytes = read_file(file);
  expect_same_parts(cached_convex_decomposition(metric_mug(), options, cache), mug_parts());
  EXPECT_EQ(read_file(file), bytes);
  EXPECT_EQ(fs::directory_iterator(cache)->path(), file);  // nothing else left there

  // A valid file under the mug's name is used as is, without recomputing: put a box's
  // decomposition there and the mug's lookup returns the box.
  const TriangleMesh box = make_unit_cube();
  const std::vector<TriangleMesh> box_parts = cached_convex_decomposition(box, options, cache);
  fs::copy_file(decomposition_cache_file(box, options, cache), file,
                fs::copy_options::overwrite_existing);
  expect_same_parts(cached_convex_decomposition(metric_mug(), options, cache), box_parts);
}

TEST(DecompositionCache, KeyCoversMeshAndOptions) {
  const fs::path dir = "/cache";
  const DecompositionOptions options;
  const fs::path file = decomposition_cache_file(metric_mug(), options, dir);
  DecompositionOptions finer = options;
  finer.resolution = 65;
  DecompositionOptions looser = options;
  looser.concavity = 0.0021;
  EXPECT_NE(decomposition_cache_file(metric_mug(), finer, dir), file);
  EXPECT_NE(decomposition_cache_file(metric_mug(), looser, dir), file);
  EXPECT_NE(decomposition_cache_file(scaled(metric_mug(), 1.0 + 1e-15), options, dir), file);
  TriangleMesh flipped = metric_mug();
  std::swap(flipped.triangles[7][1], flipped.triangles[7][2]);
  EXPECT_NE(decomposition_cache_file(flipped, options, dir), file);
  EXPECT_EQ(decomposition_cache_file(metric_mug(), options, dir), file);
}

TEST(DecompositionCache, CorruptFilesAreRecomputed) {
  ScratchDir dir;
  const TriangleMesh torus = make_torus(1.0, 0.3, 24, 12);
  const DecompositionOptions options{24, 16, 0.002, 4};
  const std::vector<TriangleMesh> parts = convex_decomposition(torus, options);
  const fs::path file = decomposition_cache_file(torus, options, dir.path());
  cached_convex_decomposition(torus, options, dir.path());
  const std::string good = read_file(file);
  std::string flipped = good;
  flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 0x10);
  const std::string corruptions[] = {
      "",      "GCVXDEC1", good.substr(0, good.size() - 1), good.substr(0, good.size() / 3),
      flipped, good + "x"};
  for (const std::string& bytes : corruptions) {
    write_file(file, bytes);
    expect_same_parts(cached_convex_decomposition(torus, options, dir.path()), parts);
    EXPECT_EQ(read_file(file), good) << "rewritten after a " << bytes.size() << "-byte file";
  }
}

}  // namespace
}  // namespace graspecmf::geometry
