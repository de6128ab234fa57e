#pragma once
// An object as one depth camera sees it, ready for grasp sampling: the object's points, the scene's
// points (for the collision check) and the table, in the frame grasps are wanted in.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "graspecmf/camera/depth_image.hpp"
#include "graspecmf/camera/intrinsics.hpp"
#include "graspecmf/geometry/plane_fit.hpp"
#include "graspecmf/lie/se3.hpp"

namespace graspecmf::camera {

// How the table under the object is found.
enum class TableMode {
  none,       // no table: grasps may come from any side
  automatic,  // fitted to the depth image's points off the object (RANSAC)
  given,      // ViewOptions::table, in the output frame
};

struct ViewOptions {
  double voxel = 0.002;         // m; the object's and scene's points are downsampled to this
  int outlier_neighbours = 16;  // statistical outlier removal on the object's points; 0: off
  double outlier_std_ratio = 2.0;
  TableMode table_mode = TableMode::none;
  geometry::Plane table;                 // TableMode::given only, output frame
  double table_inlier_distance = 0.005;  // m; points this near the fitted plane are the table
  double scene_radius = 0.3;  // m; scene points beyond this from the object are not checked
};

// Sets options.table_mode (and table) from "auto", "none" or a plane "a,b,c,d" in the output
// frame. Throws Error naming `what` for other text.
void set_table(ViewOptions& options, const std::string& text, const std::string& what);

// The object as the camera sees it, in the output frame (the base frame of output_from_camera).
struct ViewPoints {
  std::vector<lie::Vec3> object;         // the object's points, downsampled, outliers removed
  std::vector<lie::Vec3> scene;          // every point near the object (object and surroundings)
  std::optional<geometry::Plane> table;  // normal pointing to the object's side
};

// The object is the mask's non-zero pixels; with no mask, every point more than two inlier
// distances above the table (TableMode::automatic or given), else every point. Throws Error if
// the options are out of range, a size does not match, the table cannot be fitted, the object is
// not above the table, or fewer than 16 object points remain.
ViewPoints view_points(const DepthImage& depth, const Intrinsics& intrinsics,
                       const std::vector<std::uint8_t>& mask, const lie::Pose& output_from_camera,
                       const ViewOptions& options, std::uint64_t seed);

// Throws Error "<what>: the object seen is S across, smaller (larger) than a graspable object;
// <advice(larger)>" unless the points span 1 cm to 1 m (the usual sign of a wrong depth unit).
void check_view_size(const std::vector<lie::Vec3>& object, const std::string& what,
                     const std::function<std::string(bool larger)>& advice);

}  // namespace graspecmf::camera
