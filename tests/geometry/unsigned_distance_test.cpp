#include "graspecmf/geometry/unsigned_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "graspecmf/core/error.hpp"
#include "test_meshes.hpp"

namespace graspecmf::geometry {
namespace {

using testing::make_torus;
using testing::make_unit_cube;

TEST(UnsignedDistance, UnitCubeFromInsideOutsideAndAtACorner) {
  const UnsignedDistance d(make_unit_cube());
  EXPECT_NEAR(d({0.5, 0.5, 0.5}), 0.5, 1e-15);    // the centre, to every face
  EXPECT_NEAR(d({0.5, 0.2, 0.9}), 0.1, 1e-15);    // inside, nearest the top face
  EXPECT_NEAR(d({0.5, 0.5, 1.25}), 0.25, 1e-15);  // above the top face
  EXPECT_NEAR(d({2, 2, 2}), std::sqrt(3.0), 1e-15);
  EXPECT_EQ(d({0, 0.3, 0.7}), 0.0);  // on a face
}

TEST(UnsignedDistance, TorusMatchesItsClosedForm) {
  // A fine polygonal torus (R 0.1, r 0.03): distance to the ideal torus | |(ρ − R, z)| − r |
  // within the polygon's sagitta.
  const double R = 0.1, r = 0.03;
  const UnsignedDistance d(make_torus(R, r, 256, 128));
  for (const Vec3& q : {Vec3(0.1, 0, 0), Vec3(0, 0.2, 0.05), Vec3(0.07, 0.07, -0.01), Vec3(0, 0, 0),
                        Vec3(-0.12, 0.01, 0.02)}) {
    const double rho = std::hypot(q.x(), q.y());
    const double exact = std::abs(std::hypot(rho - R, q.z()) - r);
    EXPECT_NEAR(d(q), exact, 2e-4) << q.transpose();
  }
}

TEST(UnsignedDistance, AMeshWithoutAreaIsAnError) {
  TriangleMesh flat;
  flat.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  flat.triangles = {{0, 1, 2}};
  EXPECT_THROW(UnsignedDistance{flat}, Error);
  EXPECT_THROW(UnsignedDistance{TriangleMesh{}}, Error);
}

}  // namespace
}  // namespace graspecmf::geometry
