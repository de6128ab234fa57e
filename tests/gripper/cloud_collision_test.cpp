#include "graspecmf/gripper/cloud_collision.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "graspecmf/core/error.hpp"
#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/geometry/ray_cast.hpp"
#include "graspecmf/geometry/surface_sampling.hpp"
#include "graspecmf/lie/so3.hpp"
#include "test_support.hpp"

namespace graspecmf::gripper {
namespace {

// The sample mug's 2000 grasps, then each pushed 1 cm deeper along its approach axis (about
// half of those collide), checked against the mesh and against a dense surface cloud.
class CloudCollisionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    mug = geometry::scaled(geometry::read_mesh(testing::sample_mesh_file()), 0.0002682458);
    for (const auto& T : data::read_acronym_file(testing::sample_grasp_file()).transforms) {
      grasps.push_back(lie::Pose::from_matrix(T));
    }
    for (std::size_t i = 0, n = grasps.size(); i < n; ++i) {
      lie::Pose deeper = grasps[i];
      deeper.p += deeper.R.col(2) * 0.01;
      grasps.push_back(deeper);
    }
  }
  geometry::TriangleMesh mug;
  std::vector<lie::Pose> grasps;
};

TEST_F(CloudCollisionTest, FlagsOnlyMeshCollisionsAndNearlyAllOfThem) {
  const geometry::MeshRayCaster mesh(mug);
  const CloudCollisionChecker cloud(geometry::sample_surface(mug, 16384, 7).points);
  int mesh_hits = 0, cloud_hits = 0, false_alarms = 0;
  for (const lie::Pose& g : grasps) {
    const bool by_mesh = in_collision(mesh, g), by_cloud = cloud.in_collision(g);
    mesh_hits += by_mesh;
    cloud_hits += by_cloud;
    false_alarms += by_cloud && !by_mesh;
  }
  // Surface points in a box mean the box meets the surface, so the cloud never adds a collision;
  // it misses the ones that only graze the surface between samples (1142 of 1185 caught here).
  EXPECT_EQ(false_alarms, 0);
  EXPECT_GT(mesh_hits, 1000) << mesh_hits;
  EXPECT_GE(cloud_hits, 0.95 * mesh_hits) << cloud_hits << " of " << mesh_hits;
}

TEST_F(CloudCollisionTest, AnswersDoNotChangeWhenEverythingRotates) {
  const std::vector<Vec3> points = geometry::sample_surface(mug, 4096, 3).points;
  const Eigen::Matrix3d g = lie::so3_exp(Vec3(0.3, -1.1, 2.0));
  std::vector<Vec3> rotated;
  for (const Vec3& q : points) rotated.push_back(g * q);
  const CloudCollisionChecker original(points), turned(rotated);
  int differ = 0, hits = 0;
  for (const lie::Pose& x : grasps) {
    const bool a = original.in_collision(x);
    hits += a;
    differ += a != turned.in_collision({g * x.R, g * x.p});
  }
  EXPECT_GT(hits, 500);
  EXPECT_EQ(differ, 0);
}

TEST(CloudCollision, RejectsBadClouds) {
  EXPECT_THROW(CloudCollisionChecker({}), Error);
  EXPECT_THROW(CloudCollisionChecker({Vec3(0, std::nan(""), 0)}), Error);
  EXPECT_THROW(CloudCollisionChecker({Vec3::Zero()}, 0.2), Error);
}

}  // namespace
}  // namespace graspecmf::gripper
