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

// The table the object stands on, in its frame: the plane z = its lowest z.
geometry::Plane table_under(const geometry::TriangleMesh& mesh) {
  return {Eigen::Vector3d::UnitZ(), -geometry::bounding_box(mesh).min.z()};
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

std::string to_string(const InputSetting& input) {
  return std::string(input.views ? "views" : "full") + (input.table ? " above the table" : "");
}

ObjectEvaluation evaluate_object(const models::GeneratorImpl& model,
                                 const data::GraspObject& object, const models::TrainConfig& config,
                                 const std::vector<Eigen::Matrix3d>& rotations, std::size_t n,
                                 const models::SamplingSettings& settings, std::uint64_t seed,
                                 const ObjectFilter& filter, const InputSetting& input) {
  ObjectEvaluation result;
  result.name = object.name;
  const std::vector<lie::Pose> reference = reference_grasps(object, n, seed);
  result.n = reference.size();
  const auto clouds = static_cast<std::size_t>(settings.clouds);
  const auto points = static_cast<std::size_t>(config.model.encoder.points);
  const geometry::SurfacePoints cloud =
      geometry::sample_surface(object.mesh, clouds * points, seed + 1);
  std::optional<geometry::MeshRayCaster> caster;
  if (input.views) caster.emplace(object.mesh);
  Rng view_rng(seed + 1);
  const geometry::Plane table = table_under(object.mesh);
  for (std::size_t r = 0; r < rotations.size(); ++r) {
    const Eigen::Matrix3d& g = rotations[r];
    if (input.views) result.views.push_back(camera::draw_view(*input.views, view_rng));
    const std::vector<Eigen::Vector3d> seen =
        input.views
            ? camera::pick_points(camera::partial_cloud(*caster, *input.views, result.views.back()),
                                  points, clouds, view_rng)
            : cloud.points;
    const std::vector<Eigen::Vector3d> rotated_cloud = rotated(seen, g);
    std::vector<lie::Pose> rotated_reference;
    for (const lie::Pose& x : reference) rotated_reference.push_back({g * x.R, g * x.p});
    std::optional<geometry::Plane> support;
    if (input.table) support = geometry::Plane{g * table.normal, table.offset};
    std::optional<gripper::CloudGraspFilter> rotated_filter;
    if (filter.checks.any() || support) {
      rotated_filter.emplace(rotated(filter.points, g), filter.checks, gripper::panda::kMaxOpening,
                             support);
    }
    const auto start = std::chrono::steady_clock::now();
    std::size_t passed = 0;
    const std::vector<lie::Pose> generated =
        models::sample_grasps(model, rotated_cloud, config, result.n, settings, seed + 2 + r,
                              rotated_filter ? &*rotated_filter : nullptr, &passed);
    if (rotated_filter) result.passed = result.passed.value_or(0) + passed;
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

// The cloud centred on its centroid; the centroid is returned too.
std::vector<Eigen::Vector3d> centred(std::vector<Eigen::Vector3d> cloud,
                                     Eigen::Vector3d& centroid) {
  centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& q : cloud) centroid += q / static_cast<double>(cloud.size());
  for (Eigen::Vector3d& q : cloud) q -= centroid;
  return cloud;
}

// A seeded surface cloud of the object, centred on its centroid.
std::vector<Eigen::Vector3d> centred_cloud(const data::GraspObject& object, std::uint64_t seed,
                                           Eigen::Vector3d& centroid) {
  return centred(geometry::sample_surface(object.mesh, kShapePoints, seed).points, centroid);
}

// kShapePoints of what the drawn camera sees of the mesh, centred on their centroid.
std::vector<Eigen::Vector3d> centred_view(const geometry::MeshRayCaster& mesh,
                                          const camera::ViewSampling& views,
                                          const camera::ViewDraw& view, std::uint64_t seed,
                                          Eigen::Vector3d& centroid) {
  Rng rng(seed);
  return centred(
      camera::pick_points(camera::partial_cloud(mesh, views, view), kShapePoints, 1, rng),
      centroid);
}

}  // namespace

TrainingShapes::TrainingShapes(const std::vector<data::GraspObject>& objects, std::uint64_t seed,
                               const std::optional<camera::ViewSampling>& views)
    : objects_(objects), seed_(seed), views_(views), centroids_(objects.size()) {
  if (objects.empty()) throw Error("the nearest-object baseline needs training objects");
  for (std::size_t i = 0; i < objects.size(); ++i) {
    clouds_.push_back(centred_cloud(objects[i], seed, centroids_[i]));
    if (views) casters_.emplace_back(objects[i].mesh);
  }
}

std::size_t TrainingShapes::closest(
    const std::vector<Eigen::Vector3d>& cloud, const std::string& name,
    const std::function<std::vector<Eigen::Vector3d>(std::size_t)>& other) const {
  double best = std::numeric_limits<double>::infinity();
  std::optional<std::size_t> best_index;
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    if (objects_[i].name == name) continue;
    const double d = metrics::chamfer_distance(cloud, other(i));
    if (!best_index || d < best) {
      best = d;
      best_index = i;
    }
  }
  if (!best_index) throw Error(name + ": no other training object to compare with");
  return *best_index;
}

const data::GraspObject& TrainingShapes::nearest(const data::GraspObject& object,
                                                 Eigen::Vector3d& centroid,
                                                 Eigen::Vector3d& nearest_centroid) const {
  const std::size_t i = closest(centred_cloud(object, seed_, centroid), object.name,
                                [&](std::size_t j) { return clouds_[j]; });
  nearest_centroid = centroids_[i];
  return objects_[i];
}

const data::GraspObject& TrainingShapes::nearest_to_view(const data::GraspObject& object,
                                                         const camera::ViewDraw& view,
                                                         Eigen::Vector3d& centroid,
                                                         Eigen::Vector3d& nearest_centroid) const {
  if (!views_) throw Error("the nearest-object baseline was not set up for views");
  const geometry::MeshRayCaster mesh(object.mesh);
  std::vector<Eigen::Vector3d> view_centroids(objects_.size());
  const std::size_t i =
      closest(centred_view(mesh, *views_, view, seed_, centroid), object.name, [&](std::size_t j) {
        return centred_view(casters_[j], *views_, view, seed_, view_centroids[j]);
      });
  nearest_centroid = view_centroids[i];
  return objects_[i];
}

BaselineEvaluation evaluate_baselines(const data::GraspObject& object,
                                      const TrainingShapes& training, std::size_t n,
                                      std::uint64_t seed, const ObjectFilter& filter,
                                      const InputSetting& input, const camera::ViewDraw* view) {
  if (input.views && view == nullptr) throw Error("the view baseline needs the object's view");
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
  const data::GraspObject& nearest =
      input.views ? training.nearest_to_view(object, *view, centroid, neighbour_centroid)
                  : training.nearest(object, centroid, neighbour_centroid);
  result.scores.nearest = nearest.name;
  std::vector<lie::Pose> moved;
  std::optional<gripper::CloudGraspFilter> grasp_filter;
  if (filter.checks.any() || input.table) {
    std::optional<geometry::Plane> support;
    if (input.table) support = table_under(object.mesh);
    grasp_filter.emplace(filter.points, filter.checks, gripper::panda::kMaxOpening, support);
  }
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
