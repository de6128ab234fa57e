#pragma once
// The options of an object seen by one depth camera (--depth, --intrinsics, --mask,
// --camera-pose, --table, --depth-unit, --voxel) and the view's points they describe.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "graspecmf/camera/view_input.hpp"

namespace graspecmf::apps {

struct DepthInput {
  std::string depth, intrinsics, mask, camera_pose;
  std::string table = "none";  // none, auto, or a plane a,b,c,d in the output frame
  double depth_unit = 0.001;   // metres per unit of a 16-bit PNG (or an integer .npy)
  camera::ViewOptions view;

  // Adds the options to cmd.
  void add_options(CLI::App* cmd);
  // True if --depth was given.
  bool given() const { return !depth.empty(); }
  // The files the options name (for output-path checks).
  std::vector<std::filesystem::path> files() const;
  // The object's points, the scene's and the table, in the camera frame or, with --camera-pose,
  // the base frame. Throws Error if --intrinsics is missing or a file or option is bad.
  camera::ViewPoints read(std::uint64_t seed) const;
  // Throws Error unless the object seen is of a graspable size, suggesting a mask, a table or
  // another depth unit.
  void check_size(const std::vector<lie::Vec3>& object) const;
};

}  // namespace graspecmf::apps
