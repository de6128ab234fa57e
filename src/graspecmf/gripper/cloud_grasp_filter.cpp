#include "graspecmf/gripper/cloud_grasp_filter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/surface_sampling.hpp"

namespace graspecmf::gripper {
namespace {

bool inside(const Vec3& x, const Vec3& lower, const Vec3& upper) {
  return x.x() >= lower.x() && x.x() <= upper.x() && x.y() >= lower.y() && x.y() <= upper.y() &&
         x.z() >= lower.z() && x.z() <= upper.z();
}

// Object coordinates to the frame of a grasp (T_object_gripper): q ↦ Rᵀ (q − p).
class ToGripper {
 public:
  explicit ToGripper(const lie::Pose& grasp)
      : rotation_(grasp.R.transpose()), offset_(-(rotation_ * grasp.p)) {}
  Vec3 operator()(const Vec3& q) const { return rotation_ * q + offset_; }

 private:
  Eigen::Matrix3d rotation_;
  Vec3 offset_;
};

}  // namespace

std::vector<Vec3> filter_cloud(const geometry::TriangleMesh& mesh, std::uint64_t seed) {
  constexpr std::uint64_t kSeedOffset = 5;  // away from the seeds sampling and evaluation use
  return geometry::sample_surface(mesh, kFilterCloudPoints, seed + kSeedOffset).points;
}

CloudGraspFilter::CloudGraspFilter(std::vector<Vec3> points, GraspChecks checks, double opening,
                                   std::optional<geometry::Plane> support)
    : points_(std::move(points)), checks_(checks), support_(support) {
  // A filter with only a support plane checks no point.
  if (points_.empty() && checks_.any()) {
    throw Error("the grasp filter needs a non-empty point cloud");
  }
  if (!std::all_of(points_.begin(), points_.end(), [](const Vec3& q) { return q.allFinite(); })) {
    throw Error("the grasp filter's point cloud has a non-finite coordinate");
  }
  if (!checks_.any() && !support_) throw Error("the grasp filter needs at least one check");
  hand_.lower = Vec3::Constant(std::numeric_limits<double>::infinity());
  hand_.upper = -hand_.lower;
  for (const geometry::OrientedBox& box : collision_boxes(opening)) {
    // collision_boxes are axis-aligned in the gripper frame; a box bound is the box then.
    const Vec3 reach = box.pose.R.cwiseAbs() * box.half_extents;
    boxes_.push_back({box.pose.p - reach, box.pose.p + reach});
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 sign((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0,
                      (corner & 4) ? 1.0 : -1.0);
      corners_.push_back(box.pose.p + box.pose.R * sign.cwiseProduct(box.half_extents));
    }
    hand_.lower = hand_.lower.cwiseMin(boxes_.back().lower);
    hand_.upper = hand_.upper.cwiseMax(boxes_.back().upper);
  }
  gap_ = {Vec3(-0.5 * opening, -panda::kFingerHalfWidthY, panda::kFingerBaseZ),
          Vec3(0.5 * opening, panda::kFingerHalfWidthY, panda::kFingertipZ)};
}

inline bool CloudGraspFilter::in_hand(const Vec3& x) const {
  return inside(x, hand_.lower, hand_.upper) &&
         std::any_of(boxes_.begin(), boxes_.end(),
                     [&](const Bound& box) { return inside(x, box.lower, box.upper); });
}

bool CloudGraspFilter::below_support(const lie::Pose& grasp) const {
  return support_ && std::any_of(corners_.begin(), corners_.end(), [&](const Vec3& corner) {
           return support_->signed_distance(grasp.R * corner + grasp.p) < 0.0;
         });
}

bool CloudGraspFilter::in_collision(const lie::Pose& grasp) const {
  if (below_support(grasp)) return true;
  const ToGripper local(grasp);
  return std::any_of(points_.begin(), points_.end(),
                     [&](const Vec3& q) { return in_hand(local(q)); });
}

std::optional<double> CloudGraspFilter::scan_depth(const lie::Pose& grasp,
                                                   bool stop_at_collision) const {
  if (stop_at_collision && below_support(grasp)) return std::nullopt;
  const ToGripper local(grasp);
  double lowest = panda::kFingertipZ;
  for (const Vec3& q : points_) {
    const Vec3 x = local(q);
    if (stop_at_collision && in_hand(x)) return std::nullopt;
    if (inside(x, gap_.lower, gap_.upper)) lowest = std::min(lowest, x.z());
  }
  return panda::kFingertipZ - lowest;
}

double CloudGraspFilter::depth(const lie::Pose& grasp) const {
  return *scan_depth(grasp, false);
}

bool CloudGraspFilter::keeps(const lie::Pose& grasp) const {
  if (below_support(grasp)) return false;
  if (!checks_.rejects()) return true;
  if (!checks_.shallow) return !in_collision(grasp);
  const std::optional<double> reach = scan_depth(grasp, checks_.collisions);
  return reach && *reach >= kMinGraspDepth;
}

lie::Pose CloudGraspFilter::refined(const lie::Pose& grasp) const {
  if (!in_collision(grasp)) return grasp;
  // The grid's displacements (gripper frame), smallest first; ties keep the grid order.
  static const std::vector<Vec3> kDisplacements = [] {
    std::vector<Vec3> grid;
    const int back = static_cast<int>(std::lround(kRefineMaxRetreat / kRefineStep));
    const int side = static_cast<int>(std::lround(kRefineMaxSideShift / kRefineStep));
    for (int k = 0; k <= back; ++k) {
      for (int i = -side; i <= side; ++i) {
        if (k != 0 || i != 0) grid.emplace_back(i * kRefineStep, 0.0, -k * kRefineStep);
      }
    }
    std::stable_sort(grid.begin(), grid.end(),
                     [](const Vec3& a, const Vec3& b) { return a.norm() < b.norm(); });
    return grid;
  }();
  std::optional<lie::Pose> first_free;
  for (const Vec3& d : kDisplacements) {
    const lie::Pose moved{grasp.R, grasp.p + grasp.R * d};
    const std::optional<double> reach = scan_depth(moved, true);
    if (!reach) continue;
    if (*reach >= kMinGraspDepth) return moved;
    if (!first_free) first_free = moved;
  }
  return first_free ? *first_free : grasp;
}

}  // namespace graspecmf::gripper
