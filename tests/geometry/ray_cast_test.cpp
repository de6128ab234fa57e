#include "graspecmf/geometry/ray_cast.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/oriented_box.hpp"
#include "graspecmf/geometry/point_inside.hpp"
#include "graspecmf/geometry/surface_sampling.hpp"
#include "graspecmf/lie/rotation_sets.hpp"
#include "mug_fixture.hpp"
#include "test_meshes.hpp"

namespace graspecmf::geometry {
namespace {

using namespace graspecmf::geometry::testing;

// Icosphere: an icosahedron with each triangle split into 4, `levels` times, projected onto the
// sphere (20 · 4^levels outward triangles).
TriangleMesh make_sphere(const Vec3& center, double radius, int levels) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleMesh mesh;
  mesh.vertices = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                   {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto it = midpoints.find(key);
      if (it != midpoints.end()) return it->second;
      const auto index = static_cast<std::uint32_t>(mesh.vertices.size());
      mesh.vertices.push_back(0.5 * (mesh.vertices[a] + mesh.vertices[b]));
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<Triangle> finer;
    for (const Triangle& t : mesh.triangles) {
      const std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]),
                          ca = midpoint(t[2], t[0]);
      finer.insert(finer.end(), {{t[0], ab, ca}, {t[1], bc, ab}, {t[2], ca, bc}, {ab, bc, ca}});
    }
    mesh.triangles = std::move(finer);
  }
  for (Vec3& v : mesh.vertices) v = center + radius * v.normalized();
  return mesh;
}

// Nearest hit over all triangles with t in [t_min, t_max], lowest index on ties.
std::optional<std::pair<double, std::size_t>> brute_force_hit(const TriangleMesh& mesh,
                                                              const Vec3& origin, const Vec3& dir,
                                                              double t_min = 0.0,
                                                              double t_max = INFINITY) {
  std::optional<std::pair<double, std::size_t>> best;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::optional<double> hit = ray_hit(mesh, t, origin, dir);
    if (!hit || *hit < t_min || *hit > t_max) continue;
    if (!best || *hit < best->first) best = std::make_pair(*hit, t);
  }
  return best;
}

Vec3 random_direction(Rng& rng) {
  return Vec3(rng.normal(), rng.normal(), rng.normal()).normalized();
}

Vec3 random_point(const BoundingBox& box, double margin, Rng& rng) {
  Vec3 p;
  for (int k = 0; k < 3; ++k) p[k] = rng.uniform(box.min[k] - margin, box.max[k] + margin);
  return p;
}

// Casts rays from random origins around the mesh, half of them aimed at a random surface point
// and with a non-unit direction, and expects the brute-force answer; returns the number of hits.
int expect_brute_force_agreement(const TriangleMesh& mesh, int num_rays, std::uint64_t seed) {
  const MeshRayCaster caster(mesh);
  const BoundingBox box = bounding_box(mesh);
  const double size = box.extent().norm();
  Rng rng(seed);
  const SurfacePoints targets = sample_surface(mesh, static_cast<std::size_t>(num_rays), seed + 1);
  int hits = 0;
  for (int i = 0; i < num_rays; ++i) {
    const Vec3 origin = random_point(box, 0.3 * size, rng);
    const Vec3 dir =
        (i % 2 == 0) ? random_direction(rng) : rng.uniform(0.2, 5.0) * (targets.points[i] - origin);
    const auto expected = brute_force_hit(mesh, origin, dir);
    const auto actual = caster.first_hit(origin, dir);
    EXPECT_EQ(actual.has_value(), expected.has_value()) << "ray " << i;
    if (!actual || !expected) continue;
    ++hits;
    EXPECT_NEAR(actual->t, expected->first, 1e-12) << "ray " << i;
    EXPECT_EQ(actual->triangle, expected->second) << "ray " << i;
    EXPECT_LT((actual->point - (origin + actual->t * dir)).norm(), 1e-15 * (1.0 + size));
  }
  return hits;
}

TEST(RayCast, AgreesWithBruteForceOnASphere) {
  const TriangleMesh sphere = make_sphere(Vec3(0.1, -0.2, 0.3), 0.05, 3);
  ASSERT_EQ(sphere.triangles.size(), 1280u);
  const int hits = expect_brute_force_agreement(sphere, 3000, 11);
  EXPECT_GT(hits, 1600);  // all aimed rays and some random ones
}

TEST(RayCast, AgreesWithBruteForceOnTheMug) {
  const int hits = expect_brute_force_agreement(metric_mug(), 3000, 12);
  EXPECT_GT(hits, 1600);
}

TEST(RayCast, AgreesWithBruteForceFromInsideTheSphere) {
  const Vec3 center(0.0, 0.0, 0.0);
  const TriangleMesh sphere = make_sphere(center, 1.0, 2);
  const MeshRayCaster caster(sphere);
  Rng rng(13);
  for (int i = 0; i < 500; ++i) {
    const Vec3 origin = 0.9 * rng.uniform() * random_direction(rng);
    const Vec3 dir = random_direction(rng);
    const auto expected = brute_force_hit(sphere, origin, dir);
    const auto actual = caster.first_hit(origin, dir);
    ASSERT_TRUE(expected && actual) << "ray " << i;  // every ray from inside leaves the sphere
    EXPECT_NEAR(actual->t, expected->first, 1e-12);
    EXPECT_EQ(actual->triangle, expected->second);
  }
}

TEST(RayCast, MissesRaysThatPassTheMesh) {
  const MeshRayCaster caster(make_sphere(Vec3::Zero(), 1.0, 2));
  EXPECT_FALSE(caster.first_hit(Vec3(3, 0, 0), Vec3(1, 0, 0)));          // pointing away
  EXPECT_FALSE(caster.first_hit(Vec3(3, 1.5, 0), Vec3(-1, 0, 0)));       // passing beside
  EXPECT_FALSE(caster.first_hit(Vec3(0, 0, 5), Vec3(0.3, 0.3, 0.001)));  // above, nearly level
  EXPECT_TRUE(caster.first_hit(Vec3(3, 0.5, 0), Vec3(-1, 0, 0)));
}

TEST(RayCast, RespectsTMinAndTMax) {
  const TriangleMesh sphere = make_sphere(Vec3::Zero(), 1.0, 3);
  const MeshRayCaster caster(sphere);
  const Vec3 origin(-3.0, 0.01, 0.02), dir(1.0, 0.0, 0.0);
  const auto entry = caster.first_hit(origin, dir);
  ASSERT_TRUE(entry);
  EXPECT_NEAR(entry->t, 2.0, 0.02);
  const auto exit = caster.first_hit(origin, dir, entry->t + 1e-9);
  ASSERT_TRUE(exit);
  EXPECT_NEAR(exit->t, 4.0, 0.02);
  const auto brute_exit = brute_force_hit(sphere, origin, dir, entry->t + 1e-9);
  ASSERT_TRUE(brute_exit);
  EXPECT_EQ(exit->triangle, brute_exit->second);

  EXPECT_FALSE(caster.first_hit(origin, dir, 0.0, entry->t * (1.0 - 1e-9)));
  const auto at_limit = caster.first_hit(origin, dir, 0.0, entry->t);  // the range is closed
  ASSERT_TRUE(at_limit);
  EXPECT_EQ(at_limit->triangle, entry->triangle);
  EXPECT_FALSE(caster.first_hit(origin, dir, exit->t + 1e-9));
  EXPECT_FALSE(caster.first_hit(origin, dir, 3.0, 1.0));  // empty range

  // t counts multiples of the direction.
  const auto doubled = caster.first_hit(origin, 2.0 * dir);
  ASSERT_TRUE(doubled);
  EXPECT_NEAR(doubled->t, 0.5 * entry->t, 1e-12);
  EXPECT_LT((doubled->point - entry->point).norm(), 1e-12);
}

TEST(RayCast, RejectsAnEmptyMeshAndABadRay) {
  EXPECT_THROW(MeshRayCaster(TriangleMesh{}), Error);
  const MeshRayCaster caster(make_unit_cube());
  EXPECT_THROW(caster.first_hit(Vec3(2, 0.5, 0.5), Vec3::Zero()), Error);
  EXPECT_THROW(caster.first_hit(Vec3(2, 0.5, 0.5), Vec3(NAN, 0, 0)), Error);
  EXPECT_THROW(caster.first_hit(Vec3(INFINITY, 0.5, 0.5), Vec3(-1, 0, 0)), Error);
}

TEST(RayCast, KeepsItsOwnCopyOfTheMesh) {
  TriangleMesh cube = make_unit_cube();
  const MeshRayCaster caster(cube);
  cube.vertices.clear();
  const auto hit = caster.first_hit(Vec3(2, 0.5, 0.5), Vec3(-1, 0, 0));
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 1.0);
  EXPECT_EQ(caster.mesh().vertices.size(), 8u);
}

TEST(RayCast, ContainsAgreesWithTheWindingNumber) {
  const TriangleMesh torus = make_torus(1.0, 0.3, 24, 12);
  for (const TriangleMesh* mesh : {&metric_mug(), &torus}) {
    const MeshRayCaster caster(*mesh);
    const BoundingBox box = bounding_box(*mesh);
    Rng rng(14);
    int inside = 0;
    for (int i = 0; i < 3000; ++i) {
      const Vec3 q = random_point(box, 0.05 * box.extent().norm(), rng);
      const bool expected = is_inside(*mesh, q);
      EXPECT_EQ(caster.contains(q), expected) << "point " << i;
      inside += expected;
    }
    EXPECT_GT(inside, 50);
  }
}

TEST(RayCast, ContainsClassifiesPointsAroundABox) {
  // Includes points on the extensions of face planes, where a segment starts in a triangle's
  // plane without crossing the triangle.
  const MeshRayCaster caster(make_unit_cube());
  const auto in_open_unit_interval = [](double c) { return c > 0.0 && c < 1.0; };
  int inside = 0;
  for (const double x : {-0.5, 0.25, 0.5, 0.75, 1.5}) {
    for (const double y : {-0.5, 0.5, 1.5}) {
      for (const double z : {-0.5, 0.0, 0.5, 1.0, 1.5}) {
        const bool in_xy = in_open_unit_interval(x) && in_open_unit_interval(y);
        if (in_xy && (z == 0.0 || z == 1.0)) continue;  // on the surface
        const bool expected = in_xy && in_open_unit_interval(z);
        EXPECT_EQ(caster.contains(Vec3(x, y, z)), expected) << x << " " << y << " " << z;
        inside += expected;
      }
    }
  }
  EXPECT_EQ(inside, 3);
}

TEST(RayCast, ContainsFallsBackToTheWindingNumber) {
  // A zero-area triangle on a line through q makes every segment from q degenerate (q lies on the
  // triangle's plane and line); the winding number, to which it adds nothing, decides.
  TriangleMesh mesh = make_unit_cube();
  mesh.vertices.insert(mesh.vertices.end(), {{0.5, 0.5, 0.25}, {0.5, 0.5, 0.5}, {0.5, 0.5, 0.75}});
  mesh.triangles.push_back({8, 9, 10});
  const MeshRayCaster caster(mesh);
  const Vec3 q(0.5, 0.5, 0.5);
  EXPECT_TRUE(is_inside(mesh, q));
  EXPECT_TRUE(caster.contains(q));
  EXPECT_TRUE(caster.contains(Vec3(0.5, 0.25, 0.5)));
  EXPECT_FALSE(caster.contains(Vec3(0.5, 0.5, 1.5)));
}

TEST(RayCast, BoxOverlapAgreesWithTheExhaustiveTest) {
  const TriangleMesh& mug = metric_mug();
  const MeshRayCaster caster(mug);
  const BoundingBox bounds = bounding_box(mug);
  Rng rng(15);
  const auto touches_surface = [&](const OrientedBox& box) {
    for (std::size_t t = 0; t < mug.triangles.size(); ++t) {
      const Triangle& tri = mug.triangles[t];
      if (box_overlaps_triangle(box, mug.vertices[tri[0]], mug.vertices[tri[1]],
                                mug.vertices[tri[2]])) {
        return true;
      }
    }
    return false;
  };
  int overlapping = 0, inside_only = 0;
  for (int i = 0; i < 3000; ++i) {
    OrientedBox box;
    box.pose.R = lie::random_rotation(rng);
    box.pose.p = random_point(bounds, 0.02, rng);
    // Every third box is tiny, so that some lie wholly inside the mug's wall or base.
    const double scale = (i % 3 == 0) ? 2e-4 : 0.03;
    box.half_extents = Vec3(rng.uniform(0.05, 1.0), rng.uniform(0.05, 1.0), rng.uniform(0.05, 1.0));
    box.half_extents *= scale;
    const bool expected = box_overlaps_mesh(box, mug);
    EXPECT_EQ(caster.overlaps(box), expected) << "box " << i;
    overlapping += expected;
    if (i % 3 == 0) inside_only += expected && !touches_surface(box);
  }
  EXPECT_GT(overlapping, 300);
  EXPECT_LT(overlapping, 2700);
  EXPECT_GT(inside_only, 5);
}

}  // namespace
}  // namespace graspecmf::geometry
