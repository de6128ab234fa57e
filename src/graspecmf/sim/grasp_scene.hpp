#pragma once
// The MuJoCo scene of a grasp trial as MJCF text: the object (convex parts with explicit mass,
// centre of mass and inertia) and a free-floating Franka hand welded to a mocap target, with two
// force-limited finger slides. The object given here is in the world frame; the grasp trial chooses
// that frame (simulation_frame).

#include <string>
#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"
#include "graspecmf/sim/trial_config.hpp"

namespace graspecmf::sim {

struct SceneObject {
  std::vector<geometry::TriangleMesh> parts;  // convex parts, metres, object frame
  double mass = 0.0;                          // kg
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();  // about the COM, standard sign
};

// Names the trial code looks up in the compiled model.
inline constexpr const char* kObjectBody = "object";
inline constexpr const char* kHandBody = "hand";
inline constexpr const char* kTargetBody = "target";
inline constexpr const char* kLeftFinger = "left_finger";
inline constexpr const char* kRightFinger = "right_finger";

// The contacts' solref time constant for this object (TrialConfig::contact_reference_mass).
double contact_timeconst(const SceneObject& object, const TrialConfig& config);

// The step (2⁻³⁰ m, about 1 nm) to which the trial's geometric inputs are quantised in their
// object-fixed frames. The shake test is chaotic: a 1e-16 m change flips about 3 % of the labels,
// so inputs equal up to round-off must be made bit-identical to give the same labels.
inline constexpr double kRoundOffGrid = 1.0 / (1 << 30);

// The frame (in object coordinates) a trial is simulated in: origin at the centre of mass, turned
// about the gravity axis (z) to the horizontal principal axis of the inertia (signed by the parts'
// third moment along it). An object and its grasps moved together by a translation and a turn about
// gravity thus get the same trial up to round-off, and MuJoCo integrates the free object at its
// centre of mass. The identity with config.legacy_object_frame.
lie::Pose simulation_frame(const SceneObject& object, const TrialConfig& config);
// The object's parts (quantised to kRoundOffGrid), centre of mass and inertia expressed in `frame`
// (given in object coordinates).
SceneObject expressed_in(const SceneObject& object, const lie::Pose& frame);

// MJCF text of the scene; throws Error for an object without parts or with non-positive mass.
std::string grasp_scene_mjcf(const SceneObject& object, const TrialConfig& config);

}  // namespace graspecmf::sim
