#include "graspecmf/camera/view_input.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "graspecmf/camera/view_cloud.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/object_size.hpp"

namespace graspecmf::camera {
namespace {

constexpr std::size_t kMinObjectPoints = 16;

void check(const ViewOptions& o) {
  const auto non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!non_negative(o.voxel) || o.voxel > 0.05)
    throw Error("the voxel size must be in [0, 0.05] m");
  if (o.outlier_neighbours < 0 || o.outlier_neighbours > 256) {
    throw Error("the outlier neighbour count must be in [0, 256]");
  }
  if (!(o.outlier_std_ratio > 0.0) || !std::isfinite(o.outlier_std_ratio)) {
    throw Error("the outlier standard-deviation ratio must be positive");
  }
  if (!(o.table_inlier_distance > 0.0) || o.table_inlier_distance > 0.05) {
    throw Error("the table inlier distance must be in (0, 0.05] m");
  }
  if (!(o.scene_radius > 0.0) || !std::isfinite(o.scene_radius)) {
    throw Error("the scene radius must be positive");
  }
}

std::vector<lie::Vec3> moved(std::vector<lie::Vec3> points, const lie::Pose& pose) {
  for (lie::Vec3& x : points) x = pose.R * x + pose.p;
  return points;
}

lie::Vec3 centroid(const std::vector<lie::Vec3>& points) {
  lie::Vec3 sum = lie::Vec3::Zero();
  for (const lie::Vec3& x : points) sum += x;
  return sum / static_cast<double>(points.size());
}

// The plane moved by the pose.
geometry::Plane moved(const geometry::Plane& plane, const lie::Pose& pose) {
  const lie::Vec3 normal = pose.R * plane.normal;
  return {normal, plane.offset - normal.dot(pose.p)};
}

}  // namespace

ViewPoints view_points(const DepthImage& depth, const Intrinsics& intrinsics,
                       const std::vector<std::uint8_t>& mask, const lie::Pose& output_from_camera,
                       const ViewOptions& options, std::uint64_t seed) {
  check(options);
  // Everything is done in the camera frame and moved to the output frame at the end, so that
  // turning the object and the camera together turns the result exactly.
  const lie::Pose camera_from_output = lie::inverse(output_from_camera);
  const bool masked = !mask.empty();
  const std::vector<lie::Vec3> all =
      voxel_downsample(back_project(depth, intrinsics), options.voxel);
  std::optional<geometry::Plane> table;
  if (options.table_mode == TableMode::given) table = moved(options.table, camera_from_output);
  if (options.table_mode == TableMode::automatic) {
    const std::vector<lie::Vec3> off_object =
        masked ? voxel_downsample(back_project(depth, intrinsics, mask, Pixels::background),
                                  options.voxel)
               : all;
    const std::size_t min_inliers = std::max<std::size_t>(50, off_object.size() / 5);
    try {
      table = geometry::fit_plane(off_object, options.table_inlier_distance, min_inliers, seed);
    } catch (const Error& e) {
      throw Error(std::string("cannot find the table in the depth image: ") + e.what());
    }
    // The camera (the origin here) looks down at the table: the normal points to its side.
    if (table->offset < 0.0) table = geometry::Plane{-table->normal, -table->offset};
  }
  std::vector<lie::Vec3> object;
  if (masked) {
    object = voxel_downsample(back_project(depth, intrinsics, mask, Pixels::object), options.voxel);
  } else {
    for (const lie::Vec3& x : all) {
      if (!table || table->signed_distance(x) > 2.0 * options.table_inlier_distance) {
        object.push_back(x);
      }
    }
  }
  object = remove_outliers(object, options.outlier_neighbours, options.outlier_std_ratio);
  if (object.size() < kMinObjectPoints) {
    throw Error("the depth image shows " + std::to_string(object.size()) +
                " points of the object; at least " + std::to_string(kMinObjectPoints) +
                " are needed (check the mask and the depth unit)");
  }
  const lie::Vec3 middle = centroid(object);
  if (table && table->signed_distance(middle) <= 0.0) {
    throw Error(
        "the object is not above the table plane (check the plane's sign or the camera pose)");
  }
  ViewPoints view;
  for (const lie::Vec3& x : all) {
    if ((x - middle).norm() <= options.scene_radius) view.scene.push_back(x);
  }
  view.object = moved(std::move(object), output_from_camera);
  view.scene = moved(std::move(view.scene), output_from_camera);
  if (table) view.table = moved(*table, output_from_camera);
  return view;
}

void set_table(ViewOptions& options, const std::string& text, const std::string& what) {
  if (text == "auto") {
    options.table_mode = TableMode::automatic;
  } else if (text == "none") {
    options.table_mode = TableMode::none;
  } else {
    options.table_mode = TableMode::given;
    options.table = geometry::parse_plane(text, what);
  }
}

void check_view_size(const std::vector<lie::Vec3>& object, const std::string& what,
                     const std::function<std::string(bool larger)>& advice) {
  const double size = geometry::largest_side(object);
  if (size >= geometry::kMinObjectSize && size <= geometry::kMaxObjectSize) return;
  const bool larger = size > geometry::kMaxObjectSize;
  throw Error(fmt::format("{}: the object seen is {:.3g} m across, {} than a graspable object; {}",
                          what, size, larger ? "larger" : "smaller", advice(larger)));
}

}  // namespace graspecmf::camera
