#pragma once
// The MuJoCo scene of a grasp trial as MJCF text: the object (convex parts with explicit mass,
// centre of mass and inertia) and a free-floating Franka hand welded to a mocap target, with two
// force-limited finger slides. The object frame is the world frame.

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

// MJCF text of the scene; throws Error for an object without parts or with non-positive mass.
std::string grasp_scene_mjcf(const SceneObject& object, const TrialConfig& config);

}  // namespace graspecmf::sim
