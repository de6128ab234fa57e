#include "graspecmf/models/object_grasps.hpp"

#include <optional>
#include <string>

#include "graspecmf/camera/partial_view.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/surface_sampling.hpp"
#include "graspecmf/models/grasp_sampling.hpp"

namespace graspecmf::models {

std::size_t input_points(const TrainedModel& model, const SamplingSettings& settings) {
  return static_cast<std::size_t>(settings.clouds) *
         static_cast<std::size_t>(model.config.model.encoder.points);
}

ObjectPoints object_points(const geometry::TriangleMesh& mesh, std::size_t count,
                           const gripper::GraspChecks& checks, std::uint64_t seed) {
  ObjectPoints object;
  object.cloud = geometry::sample_surface(mesh, count, seed).points;
  if (checks.any()) object.filter_points = gripper::filter_cloud(mesh, seed);
  return object;
}

ObjectPoints object_points(std::vector<Eigen::Vector3d> cloud, std::size_t count,
                           const gripper::GraspChecks& checks, std::uint64_t seed) {
  ObjectPoints object;
  if (checks.any()) object.filter_points = cloud;
  Rng rng(seed);
  for (std::size_t i = 0; cloud.size() > count && i < count; ++i) {
    std::swap(cloud[i], cloud[i + rng.index(cloud.size() - i)]);
  }
  cloud.resize(std::min(cloud.size(), count));
  object.cloud = std::move(cloud);
  return object;
}

ObjectPoints object_points(camera::ViewPoints view, std::size_t points_per_cloud,
                           std::size_t clouds, const gripper::GraspChecks& checks,
                           std::uint64_t seed) {
  ObjectPoints object;
  Rng rng(seed);
  object.cloud = camera::pick_points(view.object, points_per_cloud, clouds, rng);
  if (checks.any()) object.filter_points = std::move(view.scene);
  object.support = view.table;
  return object;
}

std::vector<lie::Pose> sample_object_grasps(const TrainedModel& model, const ObjectPoints& object,
                                            std::size_t n, const SamplingSettings& settings,
                                            const gripper::GraspChecks& checks, std::uint64_t seed,
                                            std::size_t* passed) {
  const auto clouds = static_cast<std::size_t>(settings.clouds);
  const auto k = static_cast<std::size_t>(model.config.model.encoder.k);
  if (object.cloud.size() < clouds * k) {
    throw Error("the cloud has " + std::to_string(object.cloud.size()) +
                " points; the model needs at least " + std::to_string(clouds * k) +
                (clouds > 1 ? " (" + std::to_string(k) + " per cloud)" : std::string()));
  }
  std::optional<gripper::CloudGraspFilter> filter;
  if (checks.any() || object.support) {
    filter.emplace(object.filter_points, checks, gripper::panda::kMaxOpening, object.support);
  }
  return sample_grasps(*model.model, object.cloud, model.config, n, settings, seed,
                       filter ? &*filter : nullptr, passed);
}

}  // namespace graspecmf::models
