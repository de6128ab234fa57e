#include "graspecmf/gripper/cloud_collision.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/surface_sampling.hpp"

namespace graspecmf::gripper {

std::vector<Vec3> collision_cloud(const geometry::TriangleMesh& mesh, std::uint64_t seed) {
  constexpr std::uint64_t kSeedOffset = 5;  // away from the seeds sampling and evaluation use
  return geometry::sample_surface(mesh, kCollisionCloudPoints, seed + kSeedOffset).points;
}

CloudCollisionChecker::CloudCollisionChecker(std::vector<Vec3> points, double opening)
    : points_(std::move(points)), boxes_(collision_boxes(opening)) {
  if (points_.empty()) throw Error("the collision check needs a non-empty point cloud");
  if (!std::all_of(points_.begin(), points_.end(), [](const Vec3& q) { return q.allFinite(); })) {
    throw Error("the collision check's point cloud has a non-finite coordinate");
  }
  lower_ = Vec3::Constant(std::numeric_limits<double>::infinity());
  upper_ = -lower_;
  for (const geometry::OrientedBox& box : boxes_) {
    const Vec3 reach = box.pose.R.cwiseAbs() * box.half_extents;
    lower_ = lower_.cwiseMin(box.pose.p - reach);
    upper_ = upper_.cwiseMax(box.pose.p + reach);
  }
}

bool CloudCollisionChecker::in_collision(const lie::Pose& grasp) const {
  const Eigen::Matrix3d to_gripper = grasp.R.transpose();
  return std::any_of(points_.begin(), points_.end(), [&](const Vec3& q) {
    const Vec3 local = to_gripper * (q - grasp.p);
    if ((local.array() < lower_.array()).any() || (local.array() > upper_.array()).any()) {
      return false;
    }
    return std::any_of(boxes_.begin(), boxes_.end(), [&](const geometry::OrientedBox& box) {
      const Vec3 in_box = box.pose.R.transpose() * (local - box.pose.p);
      return (in_box.cwiseAbs().array() <= box.half_extents.array()).all();
    });
  });
}

}  // namespace graspecmf::gripper
