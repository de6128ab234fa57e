#include "graspecmf/eval/evaluation.hpp"

#include <chrono>
#include <limits>
#include <numeric>
#include <optional>
#include <utility>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/surface_sampling.hpp"
#include "graspecmf/gripper/panda.hpp"
#include "graspecmf/lie/rotation_sets.hpp"
#include "graspecmf/metrics/baselines.hpp"
#include "graspecmf/metrics/emd.hpp"
#include "graspecmf/models/grasp_sampling.hpp"

namespace graspecmf::eval {
namespace {

// The points rotated by g.
std::vector<Eigen::Vector3d> rotated(const std::vector<Eigen::Vector3d>& points,
                                     const Eigen::Matrix3d& g) {
  std::vector<Eigen::Vector3d> result;
  result.reserve(points.size());
  for (const Eigen::Vector3d& q : points) result.push_back(g * q);
  return result;
}

}  // namespace

std::vector<Eigen::Matrix3d> test_rotations() {
  return lie::super_fibonacci_rotations(3);
}

std::vector<lie::Pose> shuffled_grasps(const data::GraspObject& object, std::uint64_t seed) {
  std::vector<lie::Pose> grasps = object.grasps;
  Rng rng(seed);
  rng.shuffle(grasps);
  return grasps;
}

std::vector<lie::Pose> reference_grasps(const data::GraspObject& object, std::size_t n,
                                        std::uint64_t seed) {
  std::vector<lie::Pose> grasps = shuffled_grasps(object, seed);
  grasps.resize(std::min(n, grasps.size()));
  return grasps;
}

ObjectFilter object_filter(const data::GraspObject& object, const gripper::GraspChecks& checks,
                           std::uint64_t seed) {
  return {checks,
          checks.any() ? gripper::filter_cloud(object.mesh, seed) : std::vector<Eigen::Vector3d>{}};
}

ObjectEvaluation evaluate_object(const models::GeneratorImpl& model,
                                 const data::GraspObject& object, const models::TrainConfig& config,
                                 const std::vector<Eigen::Matrix3d>& rotations, std::size_t n,
                                 const models::SamplingSettings& settings, std::uint64_t seed,
                                 const ObjectFilter& filter) {
  ObjectEvaluation result;
  result.name = object.name;
  const std::vector<lie::Pose> reference = reference_grasps(object, n, seed);
  result.n = reference.size();
  const geometry::SurfacePoints cloud =
      geometry::sample_surface(object.mesh,
                               static_cast<std::size_t>(settings.clouds) *
                                   static_cast<std::size_t>(config.model.encoder.points),
                               seed + 1);
  for (std::size_t r = 0; r < rotations.size(); ++r) {
    const Eigen::Matrix3d& g = rotations[r];
    const std::vector<Eigen::Vector3d> rotated_cloud = rotated(cloud.points, g);
    std::vector<lie::Pose> rotated_reference;
    for (const lie::Pose& x : reference) rotated_reference.push_back({g * x.R, g * x.p});
    std::optional<gripper::CloudGraspFilter> rotated_filter;
    if (filter.checks.any()) rotated_filter.emplace(rotated(filter.points, g), filter.checks);
    const auto start = std::chrono::steady_clock::now();
    const std::vector<lie::Pose> generated =
        models::sample_grasps(model, rotated_cloud, config, result.n, settings, seed + 2 + r,
                              rotated_filter ? &*rotated_filter : nullptr);
    result.sampling_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.emd.push_back(metrics::earth_movers_distance(generated, rotated_reference));
    std::vector<lie::Pose>& kept = result.generated.emplace_back();
    for (const lie::Pose& x : generated) kept.push_back({g.transpose() * x.R, g.transpose() * x.p});
  }
  result.mean_emd = std::accumulate(result.emd.begin(), result.emd.end(), 0.0) /
                    static_cast<double>(result.emd.size());
  return result;
}

namespace {

constexpr std::size_t kShapePoints = 512;

// A seeded surface cloud of the object, centred on its centroid; the centroid is returned too.
std::vector<Eigen::Vector3d> centred_cloud(const data::GraspObject& object, std::uint64_t seed,
                                           Eigen::Vector3d& centroid) {
  std::vector<Eigen::Vector3d> cloud =
      geometry::sample_surface(object.mesh, kShapePoints, seed).points;
  centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& q : cloud) centroid += q / static_cast<double>(cloud.size());
  for (Eigen::Vector3d& q : cloud) q -= centroid;
  return cloud;
}

}  // namespace

TrainingShapes::TrainingShapes(const std::vector<data::GraspObject>& objects, std::uint64_t seed)
    : objects_(objects), seed_(seed), centroids_(objects.size()) {
  if (objects.empty()) throw Error("the nearest-object baseline needs training objects");
  for (std::size_t i = 0; i < objects.size(); ++i) {
    clouds_.push_back(centred_cloud(objects[i], seed, centroids_[i]));
  }
}

const data::GraspObject& TrainingShapes::nearest(const data::GraspObject& object,
                                                 Eigen::Vector3d& centroid,
                                                 Eigen::Vector3d& nearest_centroid) const {
  const std::vector<Eigen::Vector3d> cloud = centred_cloud(object, seed_, centroid);
  double best = std::numeric_limits<double>::infinity();
  std::optional<std::size_t> best_index;
  for (std::size_t i = 0; i < clouds_.size(); ++i) {
    if (objects_[i].name == object.name) continue;
    const double d = metrics::chamfer_distance(cloud, clouds_[i]);
    if (!best_index || d < best) {
      best = d;
      best_index = i;
    }
  }
  if (!best_index) throw Error(object.name + ": no other training object to compare with");
  nearest_centroid = centroids_[*best_index];
  return objects_[*best_index];
}

BaselineEvaluation evaluate_baselines(const data::GraspObject& object,
                                      const TrainingShapes& training, std::size_t n,
                                      std::uint64_t seed, const ObjectFilter& filter) {
  BaselineEvaluation result;
  const std::vector<lie::Pose> shuffled = shuffled_grasps(object, seed);
  const auto slice = [&](std::size_t offset, std::size_t count) {
    return std::vector<lie::Pose>(shuffled.begin() + static_cast<std::ptrdiff_t>(offset),
                                  shuffled.begin() + static_cast<std::ptrdiff_t>(offset + count));
  };
  const std::vector<lie::Pose> reference = slice(0, std::min(n, shuffled.size()));
  result.n = reference.size();
  if (shuffled.size() >= 2 * result.n) {
    result.scores.floor_emd = metrics::earth_movers_distance(slice(result.n, result.n), reference);
  }
  result.scores.random_emd = metrics::earth_movers_distance(
      metrics::random_grasps_in_box(geometry::bounding_box(object.mesh),
                                    gripper::panda::kPadCenterZ, result.n, seed + 1),
      reference);
  Eigen::Vector3d centroid, neighbour_centroid;
  const data::GraspObject& nearest = training.nearest(object, centroid, neighbour_centroid);
  result.scores.nearest = nearest.name;
  std::vector<lie::Pose> moved;
  std::optional<gripper::CloudGraspFilter> grasp_filter;
  if (filter.checks.any()) grasp_filter.emplace(filter.points, filter.checks);
  for (lie::Pose g : shuffled_grasps(nearest, seed)) {
    if (moved.size() == result.n) break;
    g.p += centroid - neighbour_centroid;
    if (grasp_filter && grasp_filter->refines()) g = grasp_filter->refined(g);
    if (!grasp_filter || grasp_filter->keeps(g)) moved.push_back(g);
  }
  if (moved.empty()) {
    throw Error(
        object.name + ": none of the nearest training object " + nearest.name +
        "'s grasps passes the grasp filter on it, so the nearest-object baseline has no grasps");
  }
  const std::size_t m = moved.size();  // n, or fewer if the nearest object has fewer
  result.scores.nearest_n = m;
  result.scores.nearest_emd = metrics::earth_movers_distance(
      moved, std::vector<lie::Pose>(reference.begin(),
                                    reference.begin() + static_cast<std::ptrdiff_t>(m)));
  result.nearest_grasps = std::move(moved);
  return result;
}

}  // namespace graspecmf::eval
