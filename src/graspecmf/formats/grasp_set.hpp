#pragma once
// The grasps a file holds, independent of its format: poses of the ACRONYM Panda gripper frame
// (docs/gripper.md) in one object or scene frame, with whatever labels the format carries.

#include <optional>
#include <string>
#include <vector>

#include "graspecmf/data/acronym_file.hpp"

namespace graspecmf::formats {

using Mat4 = Eigen::Matrix4d;

// Poses read from or written to files must be rigid transforms to within this (see
// lie::rigidity_error); float32 formats store rotations to about 1e-7.
inline constexpr double kRigidityTolerance = 1e-5;

struct GraspSet {
  std::vector<Mat4> poses;                        // T_frame_gripper, metres, ACRONYM gripper frame
  std::vector<double> scores;                     // empty, or one confidence per grasp
  std::vector<double> widths;                     // empty, or one finger opening (m) per grasp
  std::optional<data::GraspQualities> qualities;  // simulator labels, one entry per grasp
  std::optional<data::AcronymObjectInfo> object;  // the mesh the poses refer to

  std::size_t size() const { return poses.size(); }
};

// Throws Error "<what>: <why>" unless every pose is a finite rigid transform (kRigidityTolerance),
// scores, widths and qualities are empty or have one finite entry per grasp, and widths are ≥ 0.
void check_grasp_set(const GraspSet& grasps, const std::string& what);

// The grasps, labels and object of an ACRONYM record (its gripper must be the Panda).
GraspSet from_acronym(const data::AcronymGraspFile& record);
// An ACRONYM record (Panda gripper, opening 0.04 per finger) of the grasps; throws Error naming
// `what` if they lack the object (mesh path and scale) that ACRONYM files require.
data::AcronymGraspFile to_acronym(const GraspSet& grasps, const std::string& what);

// Grasp i's confidence for formats that store one: its score, else its success label (1 or 0),
// else 1.
double confidence(const GraspSet& grasps, std::size_t i);
// Grasp i's finger opening: its width, else the Panda's full opening (0.08 m).
double opening(const GraspSet& grasps, std::size_t i);

}  // namespace graspecmf::formats
