#include "graspecmf/gripper/panda.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "graspecmf/core/error.hpp"
#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"
#include "test_support.hpp"

namespace graspecmf::gripper {
namespace {

bool inside_box(const geometry::OrientedBox& box, const Vec3& x, double tol) {
  const Vec3 local = box.pose.R.transpose() * (x - box.pose.p);
  return (local.cwiseAbs() - box.half_extents).maxCoeff() <= tol;
}

TEST(Panda, BoxesContainTheAcronymCollisionMesh) {
  const geometry::TriangleMesh hand = geometry::read_mesh(testing::gripper_mesh_file());
  const auto boxes = collision_boxes(panda::kMaxOpening);
  ASSERT_EQ(boxes.size(), 7u);
  for (const Vec3& v : hand.vertices) {
    bool covered = false;
    for (const auto& box : boxes) covered |= inside_box(box, v, 1e-4);
    EXPECT_TRUE(covered) << "vertex " << v.transpose() << " outside the box model";
  }
}

TEST(Panda, FingersFollowTheOpening) {
  for (const double opening : {0.0, 0.03, 0.08}) {
    const auto boxes = collision_boxes(opening);
    // Pad boxes (last band of each finger) have their inner faces at ±opening/2 (0.1 mm slack).
    const geometry::OrientedBox& left_pad = boxes[3];
    const geometry::OrientedBox& right_pad = boxes[6];
    EXPECT_NEAR(left_pad.pose.p.x() + left_pad.half_extents.x(), -0.5 * opening + 1e-4, 1e-12);
    EXPECT_NEAR(right_pad.pose.p.x() - right_pad.half_extents.x(), 0.5 * opening - 1e-4, 1e-12);
    EXPECT_NEAR(right_pad.pose.p.z() + right_pad.half_extents.z(), panda::kFingertipZ, 1e-12);
  }
  EXPECT_THROW(collision_boxes(0.09), Error);
  EXPECT_THROW(collision_boxes(-0.01), Error);
}

TEST(Panda, FingerPointsAreTheCollisionMeshsRightFinger) {
  // Every finger point is a vertex of the collision mesh (to its 5-decimal rounding), and its
  // pad face sits at x = opening / 2.
  const geometry::TriangleMesh hand = geometry::read_mesh(testing::gripper_mesh_file());
  for (const Vec3& p : finger_points(panda::kMaxOpening)) {
    double nearest = 1.0;
    for (const Vec3& v : hand.vertices) nearest = std::min(nearest, (v - p).norm());
    EXPECT_LT(nearest, 1e-5) << p.transpose();
  }
  for (const double opening : {0.0, 0.05}) {
    double inner = 1.0;
    for (const Vec3& p : finger_points(opening)) inner = std::min(inner, p.x());
    EXPECT_NEAR(inner, 0.5 * opening, 2e-4);
  }
  EXPECT_THROW(finger_points(0.1), Error);
}

TEST(Panda, CollisionMeshIsSevenClosedBoxes) {
  const geometry::MeshTopology topology = geometry::analyze_topology(collision_mesh());
  EXPECT_TRUE(topology.consistently_oriented);
  EXPECT_EQ(topology.num_components, 7u);
  EXPECT_EQ(topology.genus, 0);
}

TEST(Panda, SampleGraspsAreCollisionFreeAndBadOnesCollide) {
  const geometry::TriangleMesh mug =
      geometry::scaled(geometry::read_mesh(testing::sample_mesh_file()), 0.0002682458);
  const data::AcronymGraspFile grasps = data::read_acronym_file(testing::sample_grasp_file());
  // ACRONYM's grasps are collision-free against its gripper mesh; the box model is conservative,
  // so it may flag a few that pass within a fraction of a millimetre (3 measured).
  int colliding = 0;
  for (const auto& T : grasps.transforms) colliding += in_collision(mug, lie::Pose::from_matrix(T));
  EXPECT_LE(colliding, 5) << colliding << " of 2000 flagged";

  // Palm at the mug's centre, and a grasp pushed 3 cm deeper along its approach axis.
  lie::Pose through_mug;
  through_mug.p = Vec3(0.0, 0.0, 0.1);
  EXPECT_TRUE(in_collision(mug, through_mug));
  lie::Pose deeper = lie::Pose::from_matrix(grasps.transforms[0]);
  deeper.p += deeper.R.col(2) * 0.03;
  EXPECT_TRUE(in_collision(mug, deeper));
}

TEST(Panda, MarkerMatchesAcronymDimensions) {
  const auto points = control_points(0.08);
  EXPECT_EQ(points[0], Vec3::Zero());
  EXPECT_DOUBLE_EQ(points[5].x(), 0.041);
  EXPECT_DOUBLE_EQ(points[5].z(), panda::kFingertipZ);
  EXPECT_DOUBLE_EQ(points[4].x(), -0.041);
  EXPECT_EQ(marker_segments().size(), 4u);
}

}  // namespace
}  // namespace graspecmf::gripper
