#include "graspecmf/formats/grasp_set.hpp"

#include <cmath>

#include "graspecmf/core/error.hpp"
#include "graspecmf/gripper/panda.hpp"
#include "graspecmf/lie/se3.hpp"

namespace graspecmf::formats {
namespace {

// Throws unless values is empty or has n finite entries.
void check_per_grasp(const std::vector<double>& values, std::size_t n, const std::string& name,
                     const std::string& what) {
  if (values.empty()) return;
  if (values.size() != n) {
    throw Error(what + ": " + std::to_string(values.size()) + " " + name + " for " +
                std::to_string(n) + " grasps");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(values[i])) {
      throw Error(what + ": grasp " + std::to_string(i) + "'s " + name + " is not finite");
    }
  }
}

}  // namespace

void check_grasp_set(const GraspSet& grasps, const std::string& what) {
  const std::size_t n = grasps.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double error = lie::rigidity_error(grasps.poses[i]);
    if (!(error <= kRigidityTolerance)) {
      throw Error(what + ": grasp " + std::to_string(i) +
                  " is not a rigid transform (a 4×4 [R t; 0 0 0 1] with R a rotation)");
    }
  }
  check_per_grasp(grasps.scores, n, "scores", what);
  check_per_grasp(grasps.widths, n, "widths", what);
  for (std::size_t i = 0; i < grasps.widths.size(); ++i) {
    if (grasps.widths[i] < 0) {
      throw Error(what + ": grasp " + std::to_string(i) + "'s width is negative");
    }
  }
  if (grasps.qualities) {
    const data::GraspQualities& q = *grasps.qualities;
    if (q.object_in_gripper.size() != n) {
      throw Error(what + ": " + std::to_string(q.object_in_gripper.size()) +
                  " success labels for " + std::to_string(n) + " grasps");
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (q.object_in_gripper[i] != 0 && q.object_in_gripper[i] != 1) {
        throw Error(what + ": grasp " + std::to_string(i) + "'s success label is not 0 or 1");
      }
    }
    check_per_grasp(q.motion_closing_linear, n, "closing motions", what);
    check_per_grasp(q.motion_closing_angular, n, "closing rotations", what);
    check_per_grasp(q.motion_shaking_linear, n, "shaking motions", what);
    check_per_grasp(q.motion_shaking_angular, n, "shaking rotations", what);
  }
}

GraspSet from_acronym(const data::AcronymGraspFile& record) {
  GraspSet grasps;
  grasps.poses = record.transforms;
  grasps.qualities = record.qualities;
  grasps.object = record.object;
  return grasps;
}

data::AcronymGraspFile to_acronym(const GraspSet& grasps, const std::string& what) {
  if (!grasps.object) {
    throw Error(what +
                ": ACRONYM files name the object's mesh and scale, and these grasps came "
                "without them (give them with --object and --scale)");
  }
  data::AcronymGraspFile record;
  record.transforms = grasps.poses;
  record.qualities = grasps.qualities;
  record.gripper_configuration = gripper::panda::kMaxOpening / 2;
  record.object = *grasps.object;
  return record;
}

double confidence(const GraspSet& grasps, std::size_t i) {
  if (!grasps.scores.empty()) return grasps.scores[i];
  if (grasps.qualities) return grasps.qualities->object_in_gripper[i] != 0 ? 1.0 : 0.0;
  return 1.0;
}

double opening(const GraspSet& grasps, std::size_t i) {
  return grasps.widths.empty() ? gripper::panda::kMaxOpening : grasps.widths[i];
}

}  // namespace graspecmf::formats
