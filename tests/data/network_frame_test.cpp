#include "graspecmf/data/network_frame.hpp"

#include <gtest/gtest.h>

#include "graspecmf/lie/rotation_sets.hpp"
#include "test_support.hpp"

namespace graspecmf::data {
namespace {

TEST(NetworkFrame, CentresTheRotatedCloudAndRoundTripsGrasps) {
  const std::vector<Eigen::Vector3d> cloud = {
      {0.10, 0.2, -0.3}, {0.4, -0.1, 0.0}, {-0.2, 0.3, 0.5}, {0.7, 0.7, 0.1}};
  const Eigen::Matrix3d g = lie::random_rotations(1, 3)[0];
  const NetworkFrame frame = NetworkFrame::of_points(cloud, g, 8.0);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& q : cloud) mean += frame.to_network(q) / 4.0;
  EXPECT_LT(mean.norm(), 1e-12);
  // Distances scale by 8; a grasp goes there and back exactly (to rounding).
  EXPECT_NEAR((frame.to_network(cloud[0]) - frame.to_network(cloud[1])).norm(),
              8.0 * (cloud[0] - cloud[1]).norm(), 1e-12);
  const lie::Pose grasp{lie::random_rotations(1, 4)[0], {0.3, -0.2, 0.9}};
  const lie::Pose net = frame.to_network(grasp);
  EXPECT_TRUE(net.R.isApprox(g * grasp.R, 1e-12));
  const lie::Pose back = frame.from_network(net);
  EXPECT_TRUE(back.R.isApprox(grasp.R, 1e-12));
  EXPECT_TRUE(back.p.isApprox(grasp.p, 1e-12));
  testing::expect_error([] { NetworkFrame::of_points({}, Eigen::Matrix3d::Identity(), 1.0); },
                        "at least one point");
}

}  // namespace
}  // namespace graspecmf::data
