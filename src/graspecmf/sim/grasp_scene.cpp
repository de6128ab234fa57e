#include "graspecmf/sim/grasp_scene.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/gripper/panda.hpp"

namespace graspecmf::sim {
namespace {

// Collision filtering: hand geoms (type 1, affinity 0) touch only object geoms (type 0,
// affinity 1), so fingers never collide with each other or with the palm.
constexpr const char* kHandCollision = R"(contype="1" conaffinity="0")";
constexpr const char* kObjectCollision = R"(contype="0" conaffinity="1")";

std::string vec_text(const Eigen::Vector3d& v) {
  return fmt::format("{:.17g} {:.17g} {:.17g}", v.x(), v.y(), v.z());
}

std::string mesh_asset(const geometry::TriangleMesh& part, std::size_t index) {
  std::string vertices;
  for (const auto& v : part.vertices) vertices += vec_text(v) + " ";
  return fmt::format(R"(    <mesh name="part{}" vertex="{}"/>)"
                     "\n",
                     index, vertices);
}

std::string box_geom(const geometry::OrientedBox& box, const TrialConfig& config) {
  return fmt::format(
      R"(<geom type="box" pos="{}" size="{}" friction="{} {} 0.0001" condim="4" {} mass="0"/>)",
      vec_text(box.pose.p), vec_text(box.half_extents), config.friction, config.torsional_friction,
      kHandCollision);
}

// The finger's collision mesh at zero opening: the right finger as in the collision mesh, the
// left one turned by π about z.
std::string finger_mesh_asset(const char* name, double side) {
  std::string vertices;
  for (const Eigen::Vector3d& p : gripper::finger_points(0.0)) {
    vertices += vec_text(Eigen::Vector3d(side * p.x(), side * p.y(), p.z())) + " ";
  }
  return fmt::format(R"(    <mesh name="{}" vertex="{}"/>)"
                     "\n",
                     name, vertices);
}

// A finger body on a slide along `axis`, carrying the finger mesh at zero opening.
std::string finger_body(const char* name, const char* axis, const TrialConfig& config) {
  return fmt::format(
      R"(      <body name="{0}">
        <joint name="{0}" type="slide" axis="{1}" range="0 {2}" limited="true" damping="{3}" armature="{8}"/>
        <inertial pos="0 0 0.09" mass="{4}" diaginertia="1e-5 1e-5 1e-5"/>
        <geom type="mesh" mesh="{0}" friction="{5} {6} 0.0001" condim="4" {7} mass="0"/>
      </body>
)",
      name, axis, 0.5 * gripper::panda::kMaxOpening, config.finger_damping, config.finger_mass,
      config.friction, config.torsional_friction, kHandCollision, config.finger_armature);
}

}  // namespace

double contact_timeconst(const SceneObject& object, const TrialConfig& config) {
  if (config.contact_reference_mass <= 0.0) return config.contact_timeconst;
  return std::max(
      2.0 * config.timestep,
      config.contact_timeconst * std::sqrt(object.mass / config.contact_reference_mass));
}

lie::Pose simulation_frame(const SceneObject& object, const TrialConfig& config) {
  lie::Pose frame;
  if (config.legacy_object_frame) return frame;
  frame.p = object.center_of_mass;
  // The horizontal block of the inertia turns with the object about z; its principal axis with the
  // larger moment, signed so the vertices' third moment along it is positive.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(object.inertia.topLeftCorner<2, 2>());
  Eigen::Vector3d axis(solver.eigenvectors()(0, 1), solver.eigenvectors()(1, 1), 0.0);
  double moment = 0.0;
  for (const geometry::TriangleMesh& part : object.parts) {
    moment += geometry::third_moment(part.vertices, object.center_of_mass, axis);
  }
  if (moment < 0) axis = -axis;
  frame.R = Eigen::AngleAxisd(std::atan2(axis.y(), axis.x()), Eigen::Vector3d::UnitZ())
                .toRotationMatrix();
  return frame;
}

SceneObject expressed_in(const SceneObject& object, const lie::Pose& frame) {
  const lie::Pose to_frame = lie::inverse(frame);
  SceneObject out = object;
  for (geometry::TriangleMesh& part : out.parts) {
    part = geometry::quantized(geometry::transformed(part, to_frame), kRoundOffGrid);
  }
  out.center_of_mass = lie::rounded(lie::apply(to_frame, object.center_of_mass), kRoundOffGrid);
  // The inertia on a grid 2⁻⁴⁰ of its trace's power of two: its round-off is far below the step.
  const Eigen::Matrix3d inertia = to_frame.R * object.inertia * to_frame.R.transpose();
  out.inertia = lie::rounded(inertia, std::ldexp(1.0, std::ilogb(inertia.trace()) - 40));
  return out;
}

std::string grasp_scene_mjcf(const SceneObject& object, const TrialConfig& config) {
  validate(config);
  if (object.parts.empty()) throw Error("grasp scene: the object has no convex parts");
  if (!(object.mass > 0.0)) throw Error("grasp scene: the object mass must be positive");

  std::string assets = finger_mesh_asset(kLeftFinger, -1.0) + finger_mesh_asset(kRightFinger, 1.0);
  std::string object_geoms;
  for (std::size_t i = 0; i < object.parts.size(); ++i) {
    assets += mesh_asset(object.parts[i], i);
    object_geoms += fmt::format(
        R"(      <geom type="mesh" mesh="part{}" friction="{} {} 0.0001" condim="4" {} mass="0"/>)"
        "\n",
        i, config.friction, config.torsional_friction, kObjectCollision);
  }
  const Eigen::Matrix3d& I = object.inertia;
  const std::vector<geometry::OrientedBox> boxes = gripper::collision_boxes(0.0);
  const double limit = config.finger_force;
  return fmt::format(
      R"(<mujoco model="graspecmf_grasp_trial">
  <compiler angle="radian" inertiafromgeom="false" boundmass="1e-6" boundinertia="1e-12"/>
  <option timestep="{timestep}" gravity="0 0 0" cone="elliptic" impratio="{impratio}" integrator="implicit">
    <flag multiccd="enable"/>
  </option>
  <default><geom solref="{contact_timeconst} 1" solimp="{solimp}"/></default>
  <size njmax="500" nconmax="100"/>
  <asset>
{assets}  </asset>
  <worldbody>
    <body name="{object_body}">
      <freejoint/>
      <inertial pos="{com}" mass="{mass}" fullinertia="{ixx:.17g} {iyy:.17g} {izz:.17g} {ixy:.17g} {ixz:.17g} {iyz:.17g}"/>
{object_geoms}    </body>
    <body name="{target_body}" mocap="true"/>
    <body name="{hand_body}">
      <freejoint/>
      <inertial pos="0 0 0.04" mass="{hand_mass}" diaginertia="2.5e-3 1e-3 2.5e-3"/>
      {palm}
{left}{right}    </body>
  </worldbody>
  <equality>
    <weld body1="{target_body}" body2="{hand_body}" solref="0.01 1"/>
  </equality>
  <actuator>
    <position joint="{left_name}" kp="{gain}" forcelimited="true" forcerange="{lo} {hi}"/>
    <position joint="{right_name}" kp="{gain}" forcelimited="true" forcerange="{lo} {hi}"/>
  </actuator>
</mujoco>
)",
      fmt::arg("timestep", config.timestep), fmt::arg("impratio", config.friction_impedance_ratio),
      fmt::arg("solimp", fmt::format("{} {} {}", config.contact_dmin, config.contact_dmax,
                                     config.contact_width)),
      fmt::arg("contact_timeconst", contact_timeconst(object, config)), fmt::arg("assets", assets),
      fmt::arg("object_body", kObjectBody), fmt::arg("com", vec_text(object.center_of_mass)),
      fmt::arg("mass", object.mass), fmt::arg("ixx", I(0, 0)), fmt::arg("iyy", I(1, 1)),
      fmt::arg("izz", I(2, 2)), fmt::arg("ixy", I(0, 1)), fmt::arg("ixz", I(0, 2)),
      fmt::arg("iyz", I(1, 2)), fmt::arg("object_geoms", object_geoms),
      fmt::arg("target_body", kTargetBody), fmt::arg("hand_body", kHandBody),
      fmt::arg("hand_mass", config.hand_mass), fmt::arg("palm", box_geom(boxes[0], config)),
      fmt::arg("left", finger_body(kLeftFinger, "-1 0 0", config)),
      fmt::arg("right", finger_body(kRightFinger, "1 0 0", config)),
      fmt::arg("left_name", kLeftFinger), fmt::arg("right_name", kRightFinger),
      fmt::arg("gain", config.finger_gain), fmt::arg("lo", -limit), fmt::arg("hi", limit));
}

}  // namespace graspecmf::sim
