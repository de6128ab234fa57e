#pragma once
// Collision of the open hand with an object known only by surface points (a point cloud): the
// hand collides when a point lies in one of its collision boxes (collision_boxes). A box that cuts
// the surface between samples is missed, so the answer is as good as the cloud is dense.

#include <cstdint>
#include <vector>

#include "graspecmf/gripper/panda.hpp"

namespace graspecmf::gripper {

// Surface points to sample from a mesh for these checks (about 2 mm apart on a mug, where 96 % of
// the mesh collisions of grasps pushed 1 cm too deep are caught).
inline constexpr std::size_t kCollisionCloudPoints = 16384;

// The cloud these checks use for an object known by its mesh: kCollisionCloudPoints seeded
// area-weighted surface samples, drawn apart from a model input cloud of the same seed.
std::vector<Vec3> collision_cloud(const geometry::TriangleMesh& mesh, std::uint64_t seed);

class CloudCollisionChecker {
 public:
  // Copies the points (metres, object frame). Throws Error if there are none or one is not finite,
  // or if the opening is out of range.
  explicit CloudCollisionChecker(std::vector<Vec3> points, double opening = panda::kMaxOpening);

  // True if a point lies in (or on) a collision box of the hand at `grasp` (T_object_gripper).
  bool in_collision(const lie::Pose& grasp) const;

 private:
  struct Bound {
    Vec3 lower, upper;  // an axis-aligned box in the gripper frame
  };
  std::vector<Vec3> points_;
  std::vector<Bound> boxes_;  // collision_boxes
  Vec3 lower_, upper_;        // their common bound
};

}  // namespace graspecmf::gripper
