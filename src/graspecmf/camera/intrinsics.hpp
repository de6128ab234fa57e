#pragma once
// A pinhole depth camera's intrinsics and the files they come in. Frames follow OpenCV and ROS's
// optical frame: x right, y down, z forward (the viewing direction); pixel (u, v) is column u,
// row v, with its centre at the integer coordinates.

#include <Eigen/Core>
#include <filesystem>
#include <string>

namespace graspecmf::camera {

struct Intrinsics {
  double fx = 0.0, fy = 0.0;  // focal lengths, pixels
  double cx = 0.0, cy = 0.0;  // principal point, pixels
  int width = 0, height = 0;  // image size, pixels; 0 where the file does not give it
};

// A RealSense D435's depth stream at 640 × 480: fx = fy = 615 px, principal point at the centre.
Intrinsics realsense_d435();

// Throws Error "<what>: <why>" unless fx and fy are positive and finite, cx and cy finite, and the
// size is either both 0 or both positive.
void validate(const Intrinsics& intrinsics, const std::string& what);

// Reads intrinsics from .json ({"fx", "fy", "cx", "cy"} or {"K": 9 numbers or 3 rows}, each with
// optional "width" and "height") or .yaml / .yml (a ROS CameraInfo: "K" or "k", "width",
// "height"; or a camera_calibration file: "camera_matrix": {"data"}, "image_width",
// "image_height"). Throws Error "<path>: <why>" naming the missing or bad field.
Intrinsics read_intrinsics(const std::filesystem::path& path);

// The point at depth z (metres along the viewing axis) seen at pixel (u, v).
inline Eigen::Vector3d back_project(const Intrinsics& k, double u, double v, double z) {
  return {(u - k.cx) / k.fx * z, (v - k.cy) / k.fy * z, z};
}

// The pixel coordinates (u, v) where a camera-frame point with z > 0 is seen.
inline Eigen::Vector2d project(const Intrinsics& k, const Eigen::Vector3d& x) {
  return {k.fx * x.x() / x.z() + k.cx, k.fy * x.y() / x.z() + k.cy};
}

}  // namespace graspecmf::camera
