#include "graspecmf/camera/camera_pose.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <nlohmann/json.hpp>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/json_file.hpp"

namespace graspecmf::camera {

lie::Pose read_camera_pose(const std::filesystem::path& path) {
  const std::string what = path.string();
  const nlohmann::json document = read_json_file(path);
  const nlohmann::json& rows =
      document.is_object() && document.contains("matrix") ? document["matrix"] : document;
  lie::Mat4 T;
  try {
    if (!rows.is_array() || rows.size() != 4) throw Error("");
    for (int i = 0; i < 4; ++i) {
      if (!rows[i].is_array() || rows[i].size() != 4) throw Error("");
      for (int j = 0; j < 4; ++j) T(i, j) = rows[i][j].get<double>();
    }
  } catch (const std::exception&) {
    throw Error(what +
                ": expected a 4 × 4 matrix of numbers (a list of 4 rows, or {\"matrix\": rows})");
  }
  return camera_pose_from_matrix(T, what);
}

lie::Pose camera_pose_from_matrix(const lie::Mat4& T, const std::string& what) {
  if (!T.allFinite()) throw Error(what + ": the camera pose has a non-finite entry");
  if ((T.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-9) {
    throw Error(what + ": the last row of the camera pose must be 0 0 0 1");
  }
  const lie::Mat3 R = T.topLeftCorner<3, 3>();
  if ((R.transpose() * R - lie::Mat3::Identity()).cwiseAbs().maxCoeff() > 1e-4 ||
      R.determinant() < 0.0) {
    throw Error(what + ": the camera pose's rotation block is not a rotation");
  }
  const Eigen::JacobiSVD<lie::Mat3> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  lie::Pose pose = lie::Pose::from_matrix(T);
  pose.R = svd.matrixU() * svd.matrixV().transpose();
  return pose;
}

void write_camera_pose(const lie::Pose& base_from_camera, const std::filesystem::path& path) {
  const lie::Mat4 T = base_from_camera.matrix();
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < 4; ++i) rows.push_back({T(i, 0), T(i, 1), T(i, 2), T(i, 3)});
  write_file_atomically(path, nlohmann::json{{"matrix", rows}}.dump() + "\n");
}

lie::Pose look_at(const lie::Vec3& eye, const lie::Vec3& target, const lie::Vec3& up) {
  const lie::Vec3 forward = target - eye;
  const lie::Vec3 right = forward.cross(up);
  if (forward.norm() < 1e-12 || right.norm() < 1e-9 * forward.norm() * up.norm()) {
    throw Error("look_at: the camera's view must not be zero or parallel to its up direction");
  }
  lie::Pose pose;
  pose.R.col(2) = forward.normalized();
  pose.R.col(0) = right.normalized();
  pose.R.col(1) = pose.R.col(2).cross(pose.R.col(0));  // image down
  pose.p = eye;
  return pose;
}

}  // namespace graspecmf::camera
