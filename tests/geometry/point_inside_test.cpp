#include "graspecmf/geometry/point_inside.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "test_meshes.hpp"

namespace graspecmf::geometry {
namespace {

using namespace graspecmf::geometry::testing;

Vec3 random_direction(Rng& rng) {
  return Vec3(rng.normal(), rng.normal(), rng.normal()).normalized();
}

TEST(WindingNumber, CubeCentreAndOutside) {
  const TriangleMesh cube = make_unit_cube();
  EXPECT_NEAR(winding_number(cube, Vec3(0.5, 0.5, 0.5)), 1.0, 1e-12);
  EXPECT_NEAR(winding_number(cube, Vec3(0.01, 0.98, 0.5)), 1.0, 1e-12);
  EXPECT_NEAR(winding_number(cube, Vec3(1.5, 0.5, 0.5)), 0.0, 1e-12);
  EXPECT_NEAR(winding_number(cube, Vec3(-3, 7, 2)), 0.0, 1e-12);
  EXPECT_NEAR(winding_number(cube, Vec3(1.001, 1.001, 1.001)), 0.0, 1e-12);
  EXPECT_NEAR(winding_number(inverted(cube), Vec3(0.5, 0.5, 0.5)), -1.0, 1e-12);
  EXPECT_TRUE(is_inside(cube, Vec3(0.5, 0.5, 0.5)));
  EXPECT_FALSE(is_inside(cube, Vec3(0.5, 0.5, 1.5)));
  EXPECT_FALSE(is_inside(inverted(cube), Vec3(0.5, 0.5, 0.5)));
}

TEST(WindingNumber, AgreesWithRayParityOnTheCube) {
  const TriangleMesh cube = make_unit_cube();
  Rng rng(2024);
  int inside = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec3 q(rng.uniform(-0.5, 1.5), rng.uniform(-0.5, 1.5), rng.uniform(-0.5, 1.5));
    const bool parity = ray_crossings(cube, q, random_direction(rng)) % 2 == 1;
    const double w = winding_number(cube, q);
    EXPECT_NEAR(w, parity ? 1.0 : 0.0, 1e-9) << q.transpose();
    EXPECT_EQ(is_inside(cube, q), parity) << q.transpose();
    inside += parity ? 1 : 0;
  }
  EXPECT_GT(inside, 20);  // 1/8 of the sampled volume
  EXPECT_LT(inside, 90);
}

TEST(WindingNumber, AgreesWithRayParityOnTheMug) {
  const TriangleMesh mug = scaled(read_mesh(kMugPath), kMugScale);
  const BoundingBox box = bounding_box(mug);
  Rng rng(77);
  int inside = 0;
  for (int i = 0; i < 300; ++i) {
    Vec3 q;
    for (int k = 0; k < 3; ++k) q[k] = rng.uniform(box.min[k] - 0.005, box.max[k] + 0.005);
    const bool parity = ray_crossings(mug, q, random_direction(rng)) % 2 == 1;
    EXPECT_EQ(is_inside(mug, q), parity) << q.transpose();
    EXPECT_NEAR(winding_number(mug, q), parity ? 1.0 : 0.0, 1e-6) << q.transpose();
    inside += parity ? 1 : 0;
  }
  EXPECT_GT(inside, 0);
}

TEST(WindingNumber, MugCavityWallBaseAndHandleHole) {
  // Body axis: the bounding box is symmetric in x, and the body's +y side (bbox max 0.0380) lies
  // one radius (0.0381, half the x extent) from the axis, so the axis is at x = 0, y ≈ 0; the
  // handle sticks out towards −y. Mid-height of the cup: z = 0.11.
  const TriangleMesh mug = scaled(read_mesh(kMugPath), kMugScale);
  const Vec3 cavity(0.0, 0.0, 0.11);
  EXPECT_NEAR(winding_number(mug, cavity), 0.0, 1e-9);
  EXPECT_FALSE(is_inside(mug, cavity));
  // Nothing above: the cup is open.
  EXPECT_TRUE(ray_hits(mug, cavity, Vec3::UnitZ()).empty());

  // Towards +y the ray crosses the inner and then the outer wall surface, 3.4 mm apart.
  const std::vector<double> side = ray_hits(mug, cavity, Vec3::UnitY());
  ASSERT_EQ(side.size(), 2u);
  EXPECT_NEAR(side[1] - side[0], 0.0034, 0.0006);
  const Vec3 in_wall = cavity + 0.5 * (side[0] + side[1]) * Vec3::UnitY();
  EXPECT_NEAR(winding_number(mug, in_wall), 1.0, 1e-9);
  EXPECT_TRUE(is_inside(mug, in_wall));
  EXPECT_FALSE(is_inside(mug, cavity + (side[1] + 0.001) * Vec3::UnitY()));

  // Downwards: the cavity floor and the bottom, about 4 mm apart.
  const std::vector<double> down = ray_hits(mug, cavity, -Vec3::UnitZ());
  ASSERT_EQ(down.size(), 2u);
  EXPECT_NEAR(down[1] - down[0], 0.004, 0.001);
  EXPECT_TRUE(is_inside(mug, cavity - 0.5 * (down[0] + down[1]) * Vec3::UnitZ()));

  // Towards −y at the handle's height: inner wall, outer wall, then the handle's two sides; the
  // gap between wall and handle is the hole of the genus-1 surface, outside the solid.
  const std::vector<double> back = ray_hits(mug, cavity, -Vec3::UnitY());
  ASSERT_EQ(back.size(), 4u);
  const Vec3 hole = cavity - 0.5 * (back[1] + back[2]) * Vec3::UnitY();
  EXPECT_NEAR(winding_number(mug, hole), 0.0, 1e-9);
  EXPECT_TRUE(is_inside(mug, cavity - 0.5 * (back[2] + back[3]) * Vec3::UnitY()));
}

TEST(WindingNumber, TorusHoleIsOutside) {
  const TriangleMesh torus = make_torus(1.0, 0.3, 32, 16);
  EXPECT_NEAR(winding_number(torus, Vec3::Zero()), 0.0, 1e-9);
  EXPECT_NEAR(winding_number(torus, Vec3(0.0, 1.0, 0.0)), 1.0, 1e-9);
  EXPECT_NEAR(winding_number(torus, Vec3(0.0, 0.0, 0.5)), 0.0, 1e-9);
}

}  // namespace
}  // namespace graspecmf::geometry
