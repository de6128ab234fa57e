#include "graspecmf/geometry/surface_sampling.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "test_meshes.hpp"

namespace graspecmf::geometry {
namespace {

using namespace graspecmf::geometry::testing;

// Barycentric coordinates of p in triangle t, and p's distance from the triangle's plane.
Vec3 barycentric(const TriangleMesh& mesh, std::size_t t, const Vec3& p, double& plane_distance) {
  const Vec3& a = mesh.vertices[mesh.triangles[t][0]];
  const Vec3& b = mesh.vertices[mesh.triangles[t][1]];
  const Vec3& c = mesh.vertices[mesh.triangles[t][2]];
  const Vec3 n = (b - a).cross(c - a);
  plane_distance = std::abs((p - a).dot(n.normalized()));
  const double area2 = n.squaredNorm();
  const double wb = (p - a).cross(c - a).dot(n) / area2;
  const double wc = (b - a).cross(p - a).dot(n) / area2;
  return Vec3(1.0 - wb - wc, wb, wc);
}

TEST(SurfaceSampling, PointsLieOnTheirTriangles) {
  const TriangleMesh mug = scaled(read_mesh(kMugPath), kMugScale);
  const SurfacePoints s = sample_surface(mug, 5000, 11);
  ASSERT_EQ(s.points.size(), 5000u);
  ASSERT_EQ(s.normals.size(), 5000u);
  ASSERT_EQ(s.triangles.size(), 5000u);
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const std::size_t t = s.triangles[i];
    ASSERT_LT(t, mug.triangles.size());
    double distance = 0.0;
    const Vec3 w = barycentric(mug, t, s.points[i], distance);
    EXPECT_LT(distance, 1e-15) << i;
    EXPECT_GE(w.minCoeff(), -1e-9) << i;
    EXPECT_NEAR(s.normals[i].norm(), 1.0, 1e-14) << i;
    EXPECT_TRUE(s.normals[i].isApprox(triangle_normal(mug, t), 1e-15)) << i;
  }
}

TEST(SurfaceSampling, FacesAreHitInProportionToArea) {
  // 1 × 1 × 4 box: the four long faces have 16 of the 18 area units.
  const TriangleMesh box = make_box(Vec3::Zero(), Vec3(1, 1, 4));
  const std::size_t n = 40000;
  const SurfacePoints s = sample_surface(box, n, 3);
  std::size_t on_long_faces = 0;
  for (const Vec3& p : s.points) on_long_faces += (p.z() > 1e-12 && p.z() < 4 - 1e-12) ? 1 : 0;
  const double p = 16.0 / 18.0;
  const double standard_error = std::sqrt(p * (1 - p) / n);
  EXPECT_NEAR(static_cast<double>(on_long_faces) / n, p, 4 * standard_error);
  // Each of the 12 triangles: end triangles 0.5/18, long-face triangles 2/18.
  std::vector<std::size_t> counts(box.triangles.size(), 0);
  for (const std::uint32_t t : s.triangles) ++counts[t];
  for (std::size_t t = 0; t < box.triangles.size(); ++t) {
    const double q = triangle_area(box, t) / 18.0;
    EXPECT_NEAR(static_cast<double>(counts[t]) / n, q, 4 * std::sqrt(q * (1 - q) / n)) << t;
  }
}

TEST(SurfaceSampling, UniformWithinATriangle) {
  // The half-size corner triangle at vertex 0 has a quarter of the area (without the square root
  // of the barycentric trick it would receive half of the points).
  TriangleMesh tri;
  tri.vertices = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0.5, 3, 0)};
  tri.triangles = {{0, 1, 2}};
  const std::size_t n = 40000;
  const SurfacePoints s = sample_surface(tri, n, 5);
  std::size_t near_corner = 0, left_of_median = 0;
  for (const Vec3& p : s.points) {
    double distance = 0.0;
    const Vec3 w = barycentric(tri, 0, p, distance);
    near_corner += w[0] >= 0.5 ? 1 : 0;
    left_of_median += w[1] < w[2] ? 1 : 0;  // the median from vertex 0 halves the area
  }
  const double se_quarter = std::sqrt(0.25 * 0.75 / n);
  const double se_half = std::sqrt(0.25 / n);
  EXPECT_NEAR(static_cast<double>(near_corner) / n, 0.25, 4 * se_quarter);
  EXPECT_NEAR(static_cast<double>(left_of_median) / n, 0.5, 4 * se_half);
}

TEST(SurfaceSampling, SeedsAreReproducible) {
  const TriangleMesh mug = read_mesh(kMugPath);
  const SurfacePoints a = sample_surface(mug, 256, 42);
  const SurfacePoints b = sample_surface(mug, 256, 42);
  const SurfacePoints c = sample_surface(mug, 256, 43);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_NE(a.points, c.points);
}

TEST(SurfaceSampling, SamplerDrawsFreshPointsEachCall) {
  const TriangleMesh cube = make_unit_cube();
  const SurfaceSampler sampler(cube);
  Rng rng(9);
  const SurfacePoints first = sampler.sample(64, rng);
  const SurfacePoints second = sampler.sample(64, rng);
  EXPECT_NE(first.points, second.points);
  Rng again(9);
  EXPECT_EQ(sampler.sample(64, again).points, first.points);
  EXPECT_TRUE(sampler.sample(0, rng).points.empty());
}

TEST(SurfaceSampling, ZeroAreaTrianglesAreNeverChosen) {
  TriangleMesh mesh = make_unit_cube();
  mesh.vertices.emplace_back(0.5, 0.5, 0.0);
  mesh.vertices.emplace_back(0.7, 0.5, 0.0);
  mesh.vertices.emplace_back(0.9, 0.5, 0.0);
  mesh.triangles.insert(mesh.triangles.begin(), Triangle{8, 9, 10});  // collinear, first
  mesh.triangles.push_back({8, 9, 10});                               // and last
  const SurfacePoints s = sample_surface(mesh, 2000, 1);
  for (const std::uint32_t t : s.triangles) {
    EXPECT_NE(t, 0u);
    EXPECT_NE(t, mesh.triangles.size() - 1);
  }
}

TEST(SurfaceSampling, ZeroAreaMeshThrows) {
  TriangleMesh line;
  line.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  line.triangles = {{0, 1, 2}};
  EXPECT_THROW(SurfaceSampler{line}, Error);
  EXPECT_THROW(sample_surface(TriangleMesh{}, 10, 0), Error);
}

}  // namespace
}  // namespace graspecmf::geometry
