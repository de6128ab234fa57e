#pragma once
// Grasps for one object, as `graspecmf sample` and the Python module draw them: the model's input
// cloud from a mesh or a point cloud in metres, the points the grasp filters check, and the draw.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "graspecmf/camera/view_input.hpp"
#include "graspecmf/geometry/triangle_mesh.hpp"
#include "graspecmf/gripper/cloud_grasp_filter.hpp"
#include "graspecmf/lie/se3.hpp"
#include "graspecmf/models/model_folder.hpp"

namespace graspecmf::models {

// An object as the sampler sees it, in metres in the caller's frame.
struct ObjectPoints {
  std::vector<Eigen::Vector3d> cloud;  // the model's input: settings.clouds × encoder points
  std::vector<Eigen::Vector3d> filter_points;  // what the grasp checks test (empty without checks)
  std::optional<geometry::Plane> support;  // a table under the object: no grasp reaches below it
};

// The number of input points the model takes with these settings (clouds × encoder points).
std::size_t input_points(const TrainedModel& model, const SamplingSettings& settings);

// From a mesh in metres: `count` area-weighted surface points drawn with seed, and when any check
// is on, the dense surface sample gripper::filter_cloud draws with the same seed.
ObjectPoints object_points(const geometry::TriangleMesh& mesh, std::size_t count,
                           const gripper::GraspChecks& checks, std::uint64_t seed);
// From a cloud in metres: a seeded random subset of `count` points (all of them if fewer), and
// when any check is on, every point of the cloud.
ObjectPoints object_points(std::vector<Eigen::Vector3d> cloud, std::size_t count,
                           const gripper::GraspChecks& checks, std::uint64_t seed);

// From one camera's view (camera::view_points): `clouds` draws of `points_per_cloud` of the
// object's points (camera::pick_points, as training on views draws them), when any check is on
// the scene's points, and the table as the support.
ObjectPoints object_points(camera::ViewPoints view, std::size_t points_per_cloud,
                           std::size_t clouds, const gripper::GraspChecks& checks,
                           std::uint64_t seed);

// n grasps T_object_gripper for the object (models::sample_grasps, with a CloudGraspFilter over
// its filter points and support plane when any check is on or the object has a support); `passed`
// as there. Throws Error if the cloud has fewer points than the model's neighbourhoods need.
std::vector<lie::Pose> sample_object_grasps(const TrainedModel& model, const ObjectPoints& object,
                                            std::size_t n, const SamplingSettings& settings,
                                            const gripper::GraspChecks& checks, std::uint64_t seed,
                                            std::size_t* passed = nullptr);

}  // namespace graspecmf::models
