#pragma once
// Checks of a grasp against an object known only by surface points (a point cloud), for rejecting
// implausible generated grasps (not in the paper). The open hand collides when a point lies in one
// of its collision boxes (collision_boxes); a grasp is shallow when the object reaches less than
// kMinGraspDepth into the hand between the open fingers. Both answers are as good as the cloud is
// dense: a box that cuts the surface between samples is missed.

#include <cstdint>
#include <optional>
#include <vector>

#include "graspecmf/geometry/plane_fit.hpp"
#include "graspecmf/gripper/panda.hpp"

namespace graspecmf::gripper {

// Surface points to sample from a mesh for these checks (about 2 mm apart on a mug, where 96 % of
// the mesh collisions of grasps pushed 1 cm too deep are caught).
inline constexpr std::size_t kFilterCloudPoints = 16384;

// How far below the fingertips the object must reach between the open fingers for a grasp not to
// be shallow: 1 cm of the pads' 1.76 cm. It keeps 98 % of the simulator's successful grasps of
// mugs (docs/model.md).
inline constexpr double kMinGraspDepth = 0.01;

// The cloud these checks use for an object known by its mesh: kFilterCloudPoints seeded
// area-weighted surface samples, drawn apart from a model input cloud of the same seed.
std::vector<Vec3> filter_cloud(const geometry::TriangleMesh& mesh, std::uint64_t seed);

// The search of CloudGraspFilter::refined: displacements of a colliding grasp in its own frame,
// backwards along the approach axis (z) and either way along the closing axis (x), on a grid.
inline constexpr double kRefineStep = 0.0025;        // m between grid displacements
inline constexpr double kRefineMaxRetreat = 0.02;    // m, along −z
inline constexpr double kRefineMaxSideShift = 0.01;  // m, along ±x

// Which checks a CloudGraspFilter applies.
struct GraspChecks {
  bool collisions = false;  // reject a grasp whose open hand holds a point
  bool shallow = false;     // reject a grasp whose object reaches less than kMinGraspDepth in
  bool refine = false;      // first move a grasp whose open hand holds a point (see refined)
  bool rejects() const { return collisions || shallow; }
  bool any() const { return refine || rejects(); }
};

class CloudGraspFilter {
 public:
  // Copies the points (metres, object frame). With a support plane (a table; the object on the
  // side its normal points to), a grasp whose hand reaches below it is rejected whatever the
  // checks, and counts as colliding; with a support and no check the points may be empty. Throws
  // Error if a check has no points or a point is not finite, if there is no check and no support,
  // or if the opening is out of range.
  CloudGraspFilter(std::vector<Vec3> points, GraspChecks checks,
                   double opening = panda::kMaxOpening,
                   std::optional<geometry::Plane> support = std::nullopt);

  // True if a point lies in (or on) a collision box of the hand at `grasp` (T_object_gripper), or
  // a corner of a box lies below the support plane.
  bool in_collision(const lie::Pose& grasp) const;
  // True if a corner of a collision box of the hand at `grasp` lies below the support plane
  // (false without one).
  bool below_support(const lie::Pose& grasp) const;
  // How far the object reaches into the hand at `grasp`: panda::kFingertipZ minus the lowest
  // approach-axis coordinate of a point between the open fingers (within the fingers' width, from
  // the finger bases to the tips); 0 when no point is there.
  double depth(const lie::Pose& grasp) const;
  // True if refinement was asked for (GraspChecks::refine).
  bool refines() const { return checks_.refine; }
  // True if the grasp clears the support plane and passes every rejection check asked for (one
  // pass over the cloud).
  bool keeps(const lie::Pose& grasp) const;
  // The grasp itself when its open hand holds no point. Otherwise the grasp moved by the smallest
  // displacement of the search grid (kRefine*) that frees the hand with the object still
  // kMinGraspDepth between the fingers, else the smallest that frees it, else the grasp unchanged.
  // Not in the paper; equivariant, since the search is in the grasp's own frame.
  lie::Pose refined(const lie::Pose& grasp) const;

 private:
  // True if x (gripper frame) lies in a collision box.
  bool in_hand(const Vec3& x) const;
  // One pass over the cloud at `grasp`: the depth, or nothing as soon as a point lies in a
  // collision box when stop_at_collision.
  std::optional<double> scan_depth(const lie::Pose& grasp, bool stop_at_collision) const;

  struct Bound {
    Vec3 lower, upper;  // an axis-aligned box in the gripper frame
  };
  std::vector<Vec3> points_;
  GraspChecks checks_;
  std::vector<Bound> boxes_;  // collision_boxes
  Bound hand_;                // their common bound
  Bound gap_;                 // the space between the open fingers
  std::optional<geometry::Plane> support_;
  std::vector<Vec3> corners_;  // the collision boxes' corners, gripper frame
};

}  // namespace graspecmf::gripper
