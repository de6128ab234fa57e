#include "graspecmf/metrics/baselines.hpp"

#include <gtest/gtest.h>

#include "graspecmf/core/error.hpp"

namespace graspecmf::metrics {
namespace {

TEST(Baselines, RandomGraspsFillTheGrownBoxWithRotations) {
  geometry::BoundingBox box;
  box.min = Eigen::Vector3d(-0.01, 0.0, 0.0);
  box.max = Eigen::Vector3d(0.01, 0.02, 0.1);
  const std::vector<lie::Pose> grasps = random_grasps_in_box(box, 0.05, 4000, 3);
  ASSERT_EQ(grasps.size(), 4000u);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo, mean = Eigen::Vector3d::Zero();
  for (const lie::Pose& g : grasps) {
    EXPECT_LT((g.R.transpose() * g.R - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    lo = lo.cwiseMin(g.p);
    hi = hi.cwiseMax(g.p);
    mean += g.p / 4000.0;
  }
  EXPECT_GE(lo.minCoeff() - (box.min.array() - 0.05).minCoeff(), -1e-12);
  EXPECT_TRUE(((hi.array() - (box.max.array() + 0.05)) <= 1e-12).all());
  // Nearly the whole grown box is used, and its centre is the box centre.
  EXPECT_TRUE(((hi - lo).array() > (box.extent().array() + 0.1) * 0.98).all());
  EXPECT_LT((mean - box.center()).norm(), 0.005);
  EXPECT_EQ(random_grasps_in_box(box, 0.05, 5, 3)[4].p, random_grasps_in_box(box, 0.05, 5, 3)[4].p);
  EXPECT_THROW(random_grasps_in_box(box, -1.0, 5, 3), Error);
}

TEST(Baselines, ChamferDistanceOfKnownClouds) {
  const std::vector<geometry::Vec3> a = {{0, 0, 0}, {1, 0, 0}};
  EXPECT_DOUBLE_EQ(chamfer_distance(a, a), 0.0);
  // b = a shifted by 0.1 along y: every nearest distance is 0.1, both ways.
  const std::vector<geometry::Vec3> b = {{0, 0.1, 0}, {1, 0.1, 0}};
  EXPECT_NEAR(chamfer_distance(a, b), 0.2, 1e-15);
  // One extra far point in c counts only from c's side: (0 + 0 + 5) / 3.
  const std::vector<geometry::Vec3> c = {{0, 0, 0}, {1, 0, 0}, {1, 5, 0}};
  EXPECT_NEAR(chamfer_distance(a, c), 5.0 / 3.0, 1e-15);
  EXPECT_DOUBLE_EQ(chamfer_distance(a, c), chamfer_distance(c, a));
  EXPECT_THROW(chamfer_distance({}, a), Error);
}

}  // namespace
}  // namespace graspecmf::metrics
