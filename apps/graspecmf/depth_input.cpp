#include "depth_input.hpp"

#include "cli_checks.hpp"
#include "graspecmf/camera/camera_pose.hpp"
#include "graspecmf/camera/depth_image.hpp"
#include "graspecmf/core/error.hpp"

namespace graspecmf::apps {

void DepthInput::add_options(CLI::App* cmd) {
  cmd->add_option("--depth", depth,
                  "Depth image of the object: 16-bit .png (millimetres) or .npy (float metres)");
  cmd->add_option("--intrinsics", intrinsics,
                  "Camera intrinsics for --depth: .json (fx, fy, cx, cy or K) or a ROS CameraInfo "
                  ".yaml");
  cmd->add_option("--mask", mask,
                  "Object mask for --depth (.png or .npy; non-zero on the object). Without it, "
                  "the object is what stands above --table");
  cmd->add_option("--camera-pose", camera_pose,
                  "T_base_camera (.json 4 × 4): grasps are written in the base frame, not the "
                  "camera's");
  cmd->add_option("--table", table,
                  "The support plane no grasp may reach below: auto (fitted to the depth image), "
                  "none, or a,b,c,d (a x + b y + c z + d = 0 in the output frame)")
      ->capture_default_str();
  cmd->add_option("--depth-unit", depth_unit, "Metres per unit of a 16-bit depth PNG")
      ->check(kPositiveFiniteNumber)
      ->capture_default_str();
  cmd->add_option("--voxel", view.voxel, "Downsample the view's points to this voxel size (m)")
      ->check(CLI::Range(0.0, 0.05))
      ->capture_default_str();
}

std::vector<std::filesystem::path> DepthInput::files() const {
  return {depth, intrinsics, mask, camera_pose};
}

camera::ViewPoints DepthInput::read(std::uint64_t seed) const {
  if (intrinsics.empty()) throw Error("--depth needs --intrinsics (the camera's fx, fy, cx, cy)");
  const camera::DepthImage image = camera::read_depth_image(depth, depth_unit);
  const camera::Intrinsics k = camera::read_intrinsics(intrinsics);
  const std::vector<std::uint8_t> object_mask =
      mask.empty() ? std::vector<std::uint8_t>{}
                   : camera::read_mask(mask, image.width, image.height);
  const lie::Pose pose = camera_pose.empty() ? lie::Pose{} : camera::read_camera_pose(camera_pose);
  camera::ViewOptions options = view;
  camera::set_table(options, table, "--table");
  return camera::view_points(image, k, object_mask, pose, options, seed);
}

void DepthInput::check_size(const std::vector<lie::Vec3>& object) const {
  camera::check_view_size(object, depth, [&](bool larger) {
    return std::string(larger && mask.empty() && table == "none"
                           ? "give --mask or --table auto to separate it from its surroundings"
                           : "check --depth-unit (a 16-bit PNG's unit) and that a float .npy is "
                             "in metres") +
           " (or --allow-any-size to go on)";
  });
}

}  // namespace graspecmf::apps
