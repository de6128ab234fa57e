#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>
#include <cmath>

#include "graspecmf/core/error.hpp"
#include "graspecmf/formats/format_codecs.hpp"
#include "graspecmf/gripper/panda.hpp"

namespace graspecmf::formats {
namespace {

constexpr const char* kFingerJoint = "panda_finger_joint1";
constexpr const char* kAcronymFrameName = "acronym_panda";
constexpr const char* kPandaHandName = "panda_hand";

// T_acronym_hand: the panda_hand frame in ACRONYM's gripper frame, a +90° turn about z.
Mat4 hand_in_acronym() {
  Mat4 T = Mat4::Identity();
  T.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The frame the file's poses are of: the option, else the file's gripper_frame field.
IsaacGripperFrame frame_of(const YAML::Node& document, IsaacGripperFrame option) {
  if (option != IsaacGripperFrame::automatic) return option;
  const YAML::Node field = document["gripper_frame"];
  if (field && field.IsScalar() && ends_with(field.as<std::string>(), kPandaHandName)) {
    return IsaacGripperFrame::panda_hand;
  }
  return IsaacGripperFrame::acronym;
}

double number(const YAML::Node& node, const std::string& name, const std::string& what) {
  try {
    if (node && node.IsScalar()) return node.as<double>();
  } catch (const YAML::Exception&) {
  }
  throw Error(what + ": " + name + " must be a number");
}

Eigen::Vector3d vector3(const YAML::Node& node, const std::string& name, const std::string& what) {
  if (!node || !node.IsSequence() || node.size() != 3) {
    throw Error(what + ": " + name + " must be a list of 3 numbers");
  }
  return {number(node[0], name, what), number(node[1], name, what), number(node[2], name, what)};
}

// One grasp's pose T_object_gripper from its position and (w, xyz) orientation.
Mat4 pose_of(const YAML::Node& grasp, const std::string& name, const std::string& what) {
  const YAML::Node orientation = grasp["orientation"];
  if (!orientation || !orientation.IsMap()) {
    throw Error(what + ": " + name + " has no orientation {w, xyz}");
  }
  const Eigen::Vector3d xyz = vector3(orientation["xyz"], name + ".orientation.xyz", what);
  Eigen::Quaterniond q(number(orientation["w"], name + ".orientation.w", what), xyz.x(), xyz.y(),
                       xyz.z());
  // Isaac Sim normalises what it reads; a quaternion far from unit length is a broken file.
  if (!(std::abs(q.norm() - 1) <= 1e-3)) {
    throw Error(what + ": " + name + "'s orientation is not a unit quaternion");
  }
  Mat4 T = Mat4::Identity();
  T.topLeftCorner<3, 3>() = q.normalized().toRotationMatrix();
  T.topRightCorner<3, 1>() = vector3(grasp["position"], name + ".position", what);
  return T;
}

// The grasps of a parsed isaac_grasp document.
GraspSet decoded(const YAML::Node& document, const std::string& what, IsaacGripperFrame option) {
  if (!document.IsMap() || !document["format"] || !document["format"].IsScalar() ||
      document["format"].as<std::string>() != "isaac_grasp") {
    throw Error(what + ": not an isaac_grasp file (no 'format: isaac_grasp')");
  }
  const YAML::Node list = document["grasps"];
  if (!list || !(list.IsMap() || list.IsNull())) {
    throw Error(what + ": isaac_grasp files need a 'grasps' mapping");
  }
  const Mat4 to_acronym = frame_of(document, option) == IsaacGripperFrame::panda_hand
                              ? Mat4(hand_in_acronym().inverse())
                              : Mat4(Mat4::Identity());
  GraspSet grasps;
  bool any_width = false;
  std::vector<double> widths;
  for (const auto& entry : list) {
    const std::string name = entry.first.as<std::string>();
    const YAML::Node grasp = entry.second;
    if (!grasp.IsMap()) throw Error(what + ": grasp " + name + " is not a mapping");
    grasps.poses.push_back(pose_of(grasp, name, what) * to_acronym);
    grasps.scores.push_back(
        grasp["confidence"] ? number(grasp["confidence"], name + ".confidence", what) : 1.0);
    const YAML::Node closed = grasp["cspace_position"];
    const bool has_width = closed && closed.IsMap() && closed[kFingerJoint];
    widths.push_back(has_width ? 2 * number(closed[kFingerJoint], name + ".cspace_position", what)
                               : gripper::panda::kMaxOpening);
    any_width = any_width || has_width;
  }
  if (any_width) grasps.widths = std::move(widths);
  return grasps;
}

}  // namespace

GraspSet decode_isaac_yaml(std::string_view bytes, const std::string& what,
                           IsaacGripperFrame option) {
  try {
    return decoded(YAML::Load(std::string(bytes)), what, option);
  } catch (const YAML::Exception& e) {
    throw Error(what + ": not a valid isaac_grasp YAML file (" + e.what() + ")");
  }
}

std::string encode_isaac_yaml(const GraspSet& grasps, IsaacGripperFrame option) {
  const bool hand = option != IsaacGripperFrame::acronym;
  const Mat4 to_file = hand ? hand_in_acronym() : Mat4(Mat4::Identity());
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << "isaac_grasp";
  out << YAML::Key << "format_version" << YAML::Value << "1.0";
  out << YAML::Key << "object_frame" << YAML::Value
      << (grasps.object ? grasps.object->file : std::string("object"));
  out << YAML::Key << "gripper_frame" << YAML::Value << (hand ? kPandaHandName : kAcronymFrameName);
  out << YAML::Key << "grasps" << YAML::Value << YAML::BeginMap;
  for (std::size_t i = 0; i < grasps.size(); ++i) {
    const Mat4 T = grasps.poses[i] * to_file;
    Eigen::Quaterniond q(Eigen::Matrix3d(T.topLeftCorner<3, 3>()));
    if (q.w() < 0) q.coeffs() *= -1;
    out << YAML::Key << "grasp_" + std::to_string(i) << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "confidence" << YAML::Value << confidence(grasps, i);
    out << YAML::Key << "position" << YAML::Value << YAML::Flow << YAML::BeginSeq << T(0, 3)
        << T(1, 3) << T(2, 3) << YAML::EndSeq;
    out << YAML::Key << "orientation" << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "w" << YAML::Value << q.w();
    out << YAML::Key << "xyz" << YAML::Value << YAML::Flow << YAML::BeginSeq << q.x() << q.y()
        << q.z() << YAML::EndSeq;
    out << YAML::EndMap;
    if (!grasps.widths.empty()) {
      out << YAML::Key << "cspace_position" << YAML::Value << YAML::BeginMap << YAML::Key
          << kFingerJoint << YAML::Value << grasps.widths[i] / 2 << YAML::EndMap;
    }
    out << YAML::Key << "pregrasp_cspace_position" << YAML::Value << YAML::BeginMap << YAML::Key
        << kFingerJoint << YAML::Value << gripper::panda::kMaxOpening / 2 << YAML::EndMap;
    out << YAML::EndMap;
  }
  out << YAML::EndMap << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace graspecmf::formats
