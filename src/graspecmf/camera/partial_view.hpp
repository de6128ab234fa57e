#pragma once
// Random cameras above an object standing on a table, and the partial, noisy clouds they see:
// the single views graspecmf trains on (data.input partial or mixed) and is measured on.

#include <vector>

#include "graspecmf/camera/depth_noise.hpp"
#include "graspecmf/camera/intrinsics.hpp"
#include "graspecmf/camera/view_input.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/ray_cast.hpp"
#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::camera {

// Where the cameras are drawn (uniformly in each range, azimuth in [0, 360)) and what they see.
struct ViewSampling {
  double min_elevation = 30.0, max_elevation = 70.0;  // degrees above the table
  double min_distance = 0.45, max_distance = 0.7;     // metres from the object's middle
  Intrinsics intrinsics = realsense_d435();
  bool noisy = true;  // apply `noise`; false keeps the exact rendered depth
  DepthNoise noise;
  ViewOptions points;  // voxel size and outlier removal of the object's points (no table)
};

// Throws Error "<what>: <why>" for an elevation outside [1, 89] degrees, a distance outside
// [0.15, 5] m, a reversed range, intrinsics without an image size, or bad noise parameters.
void validate(const ViewSampling& sampling, const std::string& what);

// T_base_camera of a camera at this azimuth (about z), elevation (above the table) and distance
// from the middle of box, looking at it with the image's up towards +z.
lie::Pose camera_above(const geometry::BoundingBox& box, double azimuth_degrees,
                       double elevation_degrees, double distance);

// The intrinsics of the smallest window of the image (whole pixels, clipped to the image) that
// holds everything the camera sees of the sphere (centre, radius in the base frame).
Intrinsics window_around(const Intrinsics& intrinsics, const lie::Pose& base_from_camera,
                         const lie::Vec3& centre, double radius);

// One drawn view: the camera's place and the seeds of its noise and point processing.
struct ViewDraw {
  double azimuth = 0.0, elevation = 45.0, distance = 0.55;  // degrees, degrees, metres
  std::uint64_t noise_seed = 0, points_seed = 0;
};
// A view drawn from the sampling's ranges (azimuth uniform in [0, 360)).
ViewDraw draw_view(const ViewSampling& sampling, Rng& rng);

// The object's points as the drawn camera sees them, in the mesh's frame: the mesh stands on a
// table at its lowest z, the camera is camera_above its bounding box, the view is rendered (only
// the window around the object), made noisy, back-projected through the object's mask,
// downsampled and cleaned of outliers. Throws Error if the camera sees fewer than 16 points of
// the object.
std::vector<lie::Vec3> partial_cloud(const geometry::MeshRayCaster& mesh,
                                     const ViewSampling& sampling, const ViewDraw& draw);
// The same for a view drawn from rng.
std::vector<lie::Vec3> partial_cloud(const geometry::MeshRayCaster& mesh,
                                     const ViewSampling& sampling, Rng& rng);

// `draws` independent draws of `count` of the points, one after the other: each without
// replacement, or every point and then random repeats when there are fewer than count. Throws
// Error if points is empty.
std::vector<lie::Vec3> pick_points(const std::vector<lie::Vec3>& points, std::size_t count,
                                   std::size_t draws, Rng& rng);

}  // namespace graspecmf::camera
