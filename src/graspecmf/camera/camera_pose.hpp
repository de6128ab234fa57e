#pragma once
// Camera poses: where a camera is, as the 4 × 4 transform T_base_camera from its optical frame
// (x right, y down, z forward) to a base (world, robot) frame, in JSON files and built by aiming.

#include <filesystem>
#include <string>

#include "graspecmf/lie/se3.hpp"

namespace graspecmf::camera {

// Reads T_base_camera from JSON: a 4 × 4 matrix as a list of rows, bare or as {"matrix": rows}.
// Throws Error "<path>: <why>" unless the rotation block is a rotation (to 1e-4) and the last row
// is 0 0 0 1; the rotation is re-orthonormalised.
lie::Pose read_camera_pose(const std::filesystem::path& path);

// T_base_camera from a 4 × 4 matrix, checked and re-orthonormalised as read_camera_pose does;
// errors start with `what`.
lie::Pose camera_pose_from_matrix(const lie::Mat4& T, const std::string& what);

// Writes T_base_camera as {"matrix": rows}, atomically.
void write_camera_pose(const lie::Pose& base_from_camera, const std::filesystem::path& path);

// The optical frame of a camera at `eye` looking at `target`, with the image's up direction as
// close to `up` as the view allows. Throws Error if eye = target or the view is parallel to up.
lie::Pose look_at(const lie::Vec3& eye, const lie::Vec3& target, const lie::Vec3& up);

}  // namespace graspecmf::camera
