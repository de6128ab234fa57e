#pragma once
// The Franka Panda hand in the ACRONYM gripper frame: origin at the flange, +z the approach axis,
// fingers closing along ±x. Dimensions are read off ACRONYM's franka_gripper_collision_mesh.stl.

#include <array>
#include <utility>
#include <vector>

#include "graspecmf/geometry/oriented_box.hpp"
#include "graspecmf/geometry/ray_cast.hpp"

namespace graspecmf::gripper {

using Vec3 = Eigen::Vector3d;

namespace panda {

inline constexpr double kMaxOpening = 0.08;          // distance between the finger pads, fully open
inline constexpr double kFingerBaseZ = 0.0584;       // where the fingers leave the palm
inline constexpr double kPalmTopZ = 0.066;           // highest point of the palm housing
inline constexpr double kPadCenterZ = 0.1034;        // centre of the finger pads
inline constexpr double kFingertipZ = 0.1122;        // fingertips
inline constexpr double kFingerHalfWidthY = 0.0105;  // fingers span y ∈ [−0.0105, 0.0105]
// The flat inner face of each finger (its pad): y ∈ [−kPadHalfWidthY, kPadHalfWidthY] and
// z ∈ [kPadBottomZ, kFingertipZ], centred on kPadCenterZ.
inline constexpr double kPadHalfWidthY = 0.0087;
inline constexpr double kPadBottomZ = 0.0946;

}  // namespace panda

// Throws Error unless 0 ≤ opening ≤ panda::kMaxOpening.
void check_opening(double opening);

// A conservative collision model (each box contains its part of the ACRONYM collision mesh): the
// palm housing, then three stacked boxes per finger (base, taper, tip), left finger at −x first.
// opening is the distance between the inner finger faces.
std::vector<geometry::OrientedBox> collision_boxes(double opening = panda::kMaxOpening);
// The vertices of the right (+x) finger of ACRONYM's collision mesh (its convex hull is the
// finger), with the inner pad face at x = opening / 2; the left finger is this turned by π about z.
std::vector<Vec3> finger_points(double opening = panda::kMaxOpening);
// The collision boxes as one closed mesh, for visualisation.
geometry::TriangleMesh collision_mesh(double opening = panda::kMaxOpening);
// True if the hand at `grasp` (T_object_gripper) intersects the closed object mesh.
bool in_collision(const geometry::TriangleMesh& object, const lie::Pose& grasp,
                  double opening = panda::kMaxOpening);
// The same answer through the object's BVH (much faster for many grasps on one object).
bool in_collision(const geometry::MeshRayCaster& object, const lie::Pose& grasp,
                  double opening = panda::kMaxOpening);

// ACRONYM's gripper marker as line segments: the stem from the flange to the palm, the bar across
// the palm, and the two fingers.
std::vector<std::pair<Vec3, Vec3>> marker_segments(double opening = panda::kMaxOpening);
// The marker's six control points: flange, palm centre, left/right finger bases, left/right tips.
std::array<Vec3, 6> control_points(double opening = panda::kMaxOpening);

}  // namespace graspecmf::gripper
