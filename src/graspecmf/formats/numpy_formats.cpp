#include <map>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/npy.hpp"
#include "graspecmf/core/zip_archive.hpp"
#include "graspecmf/formats/format_codecs.hpp"
#include "graspecmf/gripper/panda.hpp"

namespace graspecmf::formats {
namespace {

using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;

constexpr std::size_t kGraspNetColumns = 17;
constexpr double kGraspNetHeight = 0.02;  // GraspNet-1Billion's fixed finger height

// GraspNet's gripper axes (x approach, y closing, z = x × y) in ACRONYM's (x closing, z approach):
// R_acronym = R_graspnet · M.
Mat3 graspnet_to_acronym_axes() {
  Mat3 M;
  M << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  return M;
}

// A GraspGroup row's pose, anchored at the fingertips: the grasp point lies `depth` behind them.
Mat4 pose_of_graspnet_row(const double* row) {
  Mat3 R_graspnet;
  R_graspnet << row[4], row[5], row[6], row[7], row[8], row[9], row[10], row[11], row[12];
  const Vec3 approach = R_graspnet.col(0);
  Mat4 T = Mat4::Identity();
  T.topLeftCorner<3, 3>() = R_graspnet * graspnet_to_acronym_axes();
  T.topRightCorner<3, 1>() =
      Vec3(row[13], row[14], row[15]) + (row[3] - gripper::panda::kFingertipZ) * approach;
  return T;
}

// The archive member named `name` + ".npy", or a null pointer.
const std::string* member(const std::map<std::string, std::string>& members,
                          const std::string& name) {
  const auto it = members.find(name + ".npy");
  return it == members.end() ? nullptr : &it->second;
}

// The per-grasp vector in member `name`, which must have shape (n,).
std::vector<double> per_grasp(const std::string& bytes, const std::string& name, std::size_t n,
                              const std::string& what) {
  NpyArray array = parse_npy(bytes, what + ": " + name);
  if (array.shape != std::vector<std::size_t>{n}) {
    throw Error(what + ": " + name + " must have shape (" + std::to_string(n) + ",)");
  }
  return std::move(array.values);
}

}  // namespace

GraspSet decode_graspnet_npy(std::string_view bytes, const std::string& what) {
  const NpyArray array = parse_npy(bytes, what);
  if (array.shape.size() != 2 || array.shape[1] != kGraspNetColumns) {
    throw Error(what + ": GraspNet GraspGroup arrays have shape (N, 17)");
  }
  GraspSet grasps;
  for (std::size_t i = 0; i < array.shape[0]; ++i) {
    const double* row = &array.values[kGraspNetColumns * i];
    grasps.poses.push_back(pose_of_graspnet_row(row));
    grasps.scores.push_back(row[0]);
    grasps.widths.push_back(row[1]);
  }
  return grasps;
}

std::string encode_graspnet_npy(const GraspSet& grasps, double depth, int object_id) {
  NpyArray array{{grasps.size(), kGraspNetColumns}, {}};
  for (std::size_t i = 0; i < grasps.size(); ++i) {
    const Mat4& T = grasps.poses[i];
    const Mat3 R_graspnet = T.topLeftCorner<3, 3>() * graspnet_to_acronym_axes().transpose();
    const Vec3 point =
        T.topRightCorner<3, 1>() + (gripper::panda::kFingertipZ - depth) * T.block<3, 1>(0, 2);
    array.values.insert(array.values.end(),
                        {confidence(grasps, i), opening(grasps, i), kGraspNetHeight, depth});
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) array.values.push_back(R_graspnet(r, c));
    }
    array.values.insert(array.values.end(),
                        {point.x(), point.y(), point.z(), static_cast<double>(object_id)});
  }
  return npy_bytes(array);
}

GraspSet decode_contact_graspnet_npz(std::string_view bytes, const std::string& what) {
  std::map<std::string, std::string> members;
  for (ZipEntry& entry : read_zip_archive(bytes, what)) {
    members[entry.name] = std::move(entry.contents);
  }
  const std::string* poses = member(members, "pred_grasps_cam");
  if (!poses) throw Error(what + ": no pred_grasps_cam array (not a Contact-GraspNet result)");
  const NpyArray array = parse_npy(*poses, what + ": pred_grasps_cam");
  if (array.shape.size() != 3 || array.shape[1] != 4 || array.shape[2] != 4) {
    throw Error(what + ": pred_grasps_cam must have shape (N, 4, 4)");
  }
  const std::size_t n = array.shape[0];
  GraspSet grasps;
  for (std::size_t i = 0; i < n; ++i) {
    grasps.poses.push_back(
        Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(&array.values[16 * i]));
  }
  if (const std::string* scores = member(members, "scores")) {
    grasps.scores = per_grasp(*scores, "scores", n, what);
  }
  if (const std::string* openings = member(members, "gripper_openings")) {
    grasps.widths = per_grasp(*openings, "gripper_openings", n, what);
  }
  return grasps;
}

std::string encode_contact_graspnet_npz(const GraspSet& grasps) {
  const std::size_t n = grasps.size();
  NpyArray poses{{n, 4, 4}, {}}, scores{{n}, {}}, contacts{{n, 3}, {}}, openings{{n}, {}};
  for (std::size_t i = 0; i < n; ++i) {
    const Mat4& T = grasps.poses[i];
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) poses.values.push_back(T(r, c));
    }
    scores.values.push_back(confidence(grasps, i));
    openings.values.push_back(opening(grasps, i));
    // Contact-GraspNet's contact point: on the −x finger's pad centre line.
    const Vec3 contact = T.topRightCorner<3, 1>() - opening(grasps, i) / 2 * T.block<3, 1>(0, 0) +
                         gripper::panda::kPadCenterZ * T.block<3, 1>(0, 2);
    contacts.values.insert(contacts.values.end(), {contact.x(), contact.y(), contact.z()});
  }
  return stored_zip_archive({{"pred_grasps_cam.npy", npy_bytes(poses)},
                             {"scores.npy", npy_bytes(scores)},
                             {"contact_pts.npy", npy_bytes(contacts)},
                             {"gripper_openings.npy", npy_bytes(openings)}});
}

}  // namespace graspecmf::formats
