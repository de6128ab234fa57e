#include "graspecmf/geometry/mass_properties.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "test_meshes.hpp"

namespace graspecmf::geometry {
namespace {

using namespace graspecmf::geometry::testing;

void expect_matrix_near(const Mat3& a, const Mat3& b, double tol) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(a(i, j), b(i, j), tol) << "entry " << i << j;
  }
}

TEST(MassProperties, UnitCube) {
  const MassProperties m = mass_properties(make_unit_cube());
  EXPECT_NEAR(m.volume, 1.0, 1e-14);
  EXPECT_NEAR(m.mass, 1.0, 1e-14);
  EXPECT_TRUE(m.center_of_mass.isApprox(Vec3(0.5, 0.5, 0.5), 1e-14));
  // m (b² + c²) / 12 = 1/6 on the diagonal, no products of inertia.
  expect_matrix_near(m.inertia, Mat3::Identity() / 6.0, 1e-14);
}

TEST(MassProperties, BoxWithDensity) {
  const double a = 1.0, b = 2.0, c = 3.0, density = 2.5;
  const MassProperties m =
      mass_properties(make_box(Vec3(-1, 4, 10), Vec3(-1 + a, 4 + b, 10 + c)), density);
  const double mass = density * a * b * c;
  EXPECT_NEAR(m.volume, a * b * c, 1e-12);
  EXPECT_NEAR(m.mass, mass, 1e-12);
  EXPECT_TRUE(m.center_of_mass.isApprox(Vec3(-0.5, 5.0, 11.5), 1e-14));
  const Mat3 expected =
      Vec3(mass * (b * b + c * c) / 12, mass * (a * a + c * c) / 12, mass * (a * a + b * b) / 12)
          .asDiagonal();
  expect_matrix_near(m.inertia, expected, 1e-12);
}

TEST(MassProperties, RotatedTranslatedBoxRotatesTheTensor) {
  const TriangleMesh box = make_box(Vec3(-0.5, -1.0, -1.5), Vec3(0.5, 1.0, 1.5));  // centred
  const MassProperties body = mass_properties(box);
  lie::Pose pose;
  pose.R = Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
  pose.p = Vec3(0.3, -1.0, 2.0);
  const MassProperties moved = mass_properties(transformed(box, pose));
  EXPECT_NEAR(moved.volume, body.volume, 1e-12);
  EXPECT_TRUE(moved.center_of_mass.isApprox(pose.p, 1e-12));
  const Mat3 expected = pose.R * body.inertia * pose.R.transpose();
  expect_matrix_near(moved.inertia, expected, 1e-12);
  // Products of inertia appear, and the tensor stays symmetric positive-definite.
  EXPECT_GT(std::abs(moved.inertia(0, 1)), 0.01);
  EXPECT_TRUE(moved.inertia.isApprox(moved.inertia.transpose(), 1e-14));
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat3>(moved.inertia).eigenvalues().minCoeff(), 0.0);
}

TEST(MassProperties, FarFromTheOriginStaysAccurate) {
  lie::Pose pose;
  pose.p = Vec3(1e4, -2e4, 3e4);
  const MassProperties m = mass_properties(transformed(make_unit_cube(), pose));
  EXPECT_NEAR(m.volume, 1.0, 1e-9);
  expect_matrix_near(m.inertia, Mat3::Identity() / 6.0, 1e-9);
}

TEST(MassProperties, InvertedMeshHasNegativeVolume) {
  const MassProperties m = mass_properties(inverted(make_box(Vec3::Zero(), Vec3(1, 2, 3))));
  EXPECT_NEAR(m.volume, -6.0, 1e-12);
  EXPECT_TRUE(m.center_of_mass.isApprox(Vec3(0.5, 1.0, 1.5), 1e-14));
}

TEST(MassProperties, ZeroVolumeThrows) {
  TriangleMesh flat;
  flat.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  flat.triangles = {{0, 1, 2}, {1, 3, 2}, {0, 2, 1}, {1, 2, 3}};  // a doubled square
  EXPECT_THROW(mass_properties(flat), Error);
  EXPECT_THROW(mass_properties(TriangleMesh{}), Error);
}

// /object/* of the mug's grasp file, read once with
//   h5dump -m "%.17g" -d /object/com -d /object/inertia -d /object/volume -d /object/density
//     data/acronym-sample/grasps/Mug_10f6e09036350e92b3f21f1137c3c347_0.0002682457830986903.h5
// (the file stores them rounded to about 6 significant digits).
constexpr double kFileVolume = 8.72532e-05;
constexpr double kFileDensity = 150.0;
const Vec3 kFileCom(6.8594e-06, -0.00212206, 0.0938568045);
Mat3 file_inertia() {
  Mat3 I;
  I << 2.24212e-05, 9.08e-08, 4.4e-09,    //
      9.08e-08, 2.09481e-05, -6.264e-07,  //
      4.4e-09, -6.264e-07, 1.64619e-05;
  return I;
}

TEST(MassProperties, MugMatchesTheGraspFile) {
  const TriangleMesh mug = scaled(read_mesh(kMugPath), kMugScale);
  const MassProperties m = mass_properties(mug, kFileDensity);
  EXPECT_GT(m.volume, 0.0);
  EXPECT_NEAR(m.volume, kFileVolume, 1e-5 * kFileVolume);
  EXPECT_NEAR(m.mass, 0.0130879738, 1e-5 * 0.0130879738);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(m.center_of_mass[k], kFileCom[k], 1e-8) << k;
  // Same diagonal; ACRONYM's products of inertia carry the opposite sign of the standard tensor.
  const Mat3 file = file_inertia();
  const double largest = file.cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double expected = i == j ? file(i, j) : -file(i, j);
      EXPECT_NEAR(m.inertia(i, j), expected, 1e-4 * largest) << "entry " << i << j;
    }
  }
}

// The principal frame moves rigidly with the mesh: for the sample mug moved by metres and turned,
// it is the moved frame of the unmoved mug, to round-off.
TEST(MassProperties, PrincipalFrameMovesWithTheMesh) {
  const TriangleMesh mug = scaled(read_mesh(kMugPath), kMugScale);
  const lie::Pose frame = principal_frame(mug);
  EXPECT_NEAR((frame.R.transpose() * frame.R - Mat3::Identity()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(frame.R.determinant(), 1.0, 1e-12);
  EXPECT_NEAR((frame.p - kFileCom).norm(), 0.0, 1e-8);
  for (const auto& [axis, angle] : {std::pair{Vec3(0, 0, 1), 0.7}, {Vec3(1, 2, 3), 2.9}}) {
    lie::Pose motion;
    motion.R = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
    motion.p = Vec3(2.7, 1.2, -0.5);
    const lie::Pose moved = principal_frame(transformed(mug, motion));
    const lie::Pose expected = lie::compose(motion, frame);
    EXPECT_LT((moved.R - expected.R).norm(), 1e-9) << "angle " << angle;
    EXPECT_LT((moved.p - expected.p).norm(), 1e-9) << "angle " << angle;
  }
}

}  // namespace
}  // namespace graspecmf::geometry
