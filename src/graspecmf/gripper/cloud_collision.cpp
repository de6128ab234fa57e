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
    : points_(std::move(points)) {
  if (points_.empty()) throw Error("the collision check needs a non-empty point cloud");
  if (!std::all_of(points_.begin(), points_.end(), [](const Vec3& q) { return q.allFinite(); })) {
    throw Error("the collision check's point cloud has a non-finite coordinate");
  }
  lower_ = Vec3::Constant(std::numeric_limits<double>::infinity());
  upper_ = -lower_;
  for (const geometry::OrientedBox& box : collision_boxes(opening)) {
    // collision_boxes are axis-aligned in the gripper frame; a box bound is the box then.
    const Vec3 reach = box.pose.R.cwiseAbs() * box.half_extents;
    boxes_.push_back({box.pose.p - reach, box.pose.p + reach});
    lower_ = lower_.cwiseMin(boxes_.back().lower);
    upper_ = upper_.cwiseMax(boxes_.back().upper);
  }
}

bool CloudCollisionChecker::in_collision(const lie::Pose& grasp) const {
  const Eigen::Matrix3d to_gripper = grasp.R.transpose();
  const Vec3 offset = -(to_gripper * grasp.p);
  const auto inside = [](const Vec3& x, const Vec3& lower, const Vec3& upper) {
    return x.x() >= lower.x() && x.x() <= upper.x() && x.y() >= lower.y() && x.y() <= upper.y() &&
           x.z() >= lower.z() && x.z() <= upper.z();
  };
  return std::any_of(points_.begin(), points_.end(), [&](const Vec3& q) {
    const Vec3 local = to_gripper * q + offset;
    return inside(local, lower_, upper_) &&
           std::any_of(boxes_.begin(), boxes_.end(),
                       [&](const Bound& box) { return inside(local, box.lower, box.upper); });
  });
}

}  // namespace graspecmf::gripper
