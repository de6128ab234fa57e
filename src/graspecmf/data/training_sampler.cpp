#include "graspecmf/data/training_sampler.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>

#include "graspecmf/core/error.hpp"
#include "graspecmf/data/network_frame.hpp"
#include "graspecmf/gripper/panda.hpp"
#include "graspecmf/lie/rotation_sets.hpp"

namespace graspecmf::data {

Augmentation parse_augmentation(const std::string& name) {
  if (name == "none") return Augmentation::none;
  if (name == "z") return Augmentation::z;
  if (name == "so3") return Augmentation::so3;
  throw Error("unknown augmentation '" + name + "' (expected none, z or so3)");
}

std::string to_string(Augmentation augmentation) {
  switch (augmentation) {
    case Augmentation::none:
      return "none";
    case Augmentation::z:
      return "z";
    case Augmentation::so3:
      return "so3";
  }
  return "?";
}

CloudInput parse_cloud_input(const std::string& name) {
  if (name == "full") return CloudInput::full;
  if (name == "partial") return CloudInput::partial;
  if (name == "mixed") return CloudInput::mixed;
  throw Error("unknown input '" + name + "' (expected full, partial or mixed)");
}

std::string to_string(CloudInput input) {
  switch (input) {
    case CloudInput::full:
      return "full";
    case CloudInput::partial:
      return "partial";
    case CloudInput::mixed:
      return "mixed";
  }
  return "?";
}

ObjectSample make_object_sample(const geometry::SurfacePoints& cloud,
                                const std::vector<lie::Pose>& grasps, const Eigen::Matrix3d& g,
                                double position_scale) {
  if (cloud.points.empty()) throw Error("an object sample needs at least one point");
  const NetworkFrame frame = NetworkFrame::of_points(cloud.points, g, position_scale);
  ObjectSample sample;
  sample.rotation = g;
  sample.scale = position_scale;
  sample.centroid = frame.centroid;
  const auto push = [&](std::vector<float>& out, const Eigen::Vector3d& v) {
    for (int k = 0; k < 3; ++k) out.push_back(static_cast<float>(v[k]));
  };
  for (const Eigen::Vector3d& q : cloud.points) push(sample.points, frame.to_network(q));
  for (const lie::Pose& grasp : grasps) {
    const lie::Pose x = frame.to_network(grasp);
    for (int r = 0; r < 3; ++r) push(sample.rotations, x.R.row(r).transpose());
    push(sample.positions, x.p);
  }
  return sample;
}

void stretch_object(geometry::SurfacePoints& cloud, std::vector<lie::Pose>& grasps,
                    const Eigen::Vector3d& factors) {
  const Eigen::Vector3d inverse = factors.cwiseInverse();
  for (Eigen::Vector3d& q : cloud.points) q = q.cwiseProduct(factors);
  for (Eigen::Vector3d& n : cloud.normals) n = n.cwiseProduct(inverse).normalized();
  for (lie::Pose& grasp : grasps) {
    const Eigen::Vector3d pad = grasp.R.col(2) * gripper::panda::kPadCenterZ;
    grasp.p = (grasp.p + pad).cwiseProduct(factors) - pad;
  }
}

DistanceSamples near_surface_distances(const geometry::SurfaceSampler& surface,
                                       const geometry::UnsignedDistance& distance,
                                       std::size_t count, double radius, Rng& rng) {
  DistanceSamples out;
  out.points = surface.sample(count, rng).points;
  for (std::size_t i = 0; i < count; ++i) {
    const double sigma = (i % 2 == 0 ? 0.05 : 0.0158) * radius;
    Eigen::Vector3d& q = out.points[i];
    for (int k = 0; k < 3; ++k) q[k] += sigma * rng.normal();
    out.distances.push_back(distance(q));
  }
  return out;
}

TrainingSampler::TrainingSampler(std::vector<GraspObject> objects,
                                 const TrainingSamplerOptions& options, std::uint64_t seed)
    : objects_(std::move(objects)), options_(options), rng_(seed) {
  if (objects_.empty()) throw Error("training needs at least one object");
  if (options.objects_per_step == 0 || options.points == 0 || !(options.position_scale > 0)) {
    throw Error("training sampler: objects_per_step, points and position_scale must be positive");
  }
  if (!(options.stretch >= 0 && options.stretch < 0.5)) {
    throw Error("training sampler: stretch must be in [0, 0.5)");
  }
  if (options.input != CloudInput::full) camera::validate(options.views, "training views");
  surfaces_.reserve(objects_.size());
  for (const GraspObject& object : objects_) {
    if (object.grasps.empty()) throw Error("object " + object.name + " has no successful grasp");
    surfaces_.emplace_back(object.mesh);  // objects_ is never resized, so the reference holds
    if (options.distance_points > 0) {
      distances_.emplace_back(object.mesh);
      radii_.push_back(0.5 * geometry::bounding_box(object.mesh).extent().norm());
    }
    if (options.input != CloudInput::full) casters_.emplace_back(object.mesh);
  }
}

geometry::SurfacePoints TrainingSampler::input_cloud(std::size_t index) {
  // The full setting draws nothing extra, so that its runs stay as they were.
  const bool partial = options_.input == CloudInput::partial ||
                       (options_.input == CloudInput::mixed && rng_.uniform() < 0.5);
  if (!partial) return surfaces_[index].sample(options_.points, rng_);
  geometry::SurfacePoints cloud;
  cloud.points = camera::pick_points(camera::partial_cloud(casters_[index], options_.views, rng_),
                                     options_.points, 1, rng_);
  return cloud;
}

std::vector<ObjectSample> TrainingSampler::next_step() {
  std::vector<ObjectSample> step;
  for (std::size_t k = 0; k < options_.objects_per_step; ++k) {
    if (cursor_ == order_.size()) {  // a new epoch in a fresh order
      order_.resize(objects_.size());
      std::iota(order_.begin(), order_.end(), std::size_t{0});
      rng_.shuffle(order_);
      cursor_ = 0;
    }
    const std::size_t index = order_[cursor_++];
    const GraspObject& object = objects_[index];
    // A partial Fisher–Yates shuffle picks the grasps without replacement.
    std::vector<std::size_t> pick(object.grasps.size());
    std::iota(pick.begin(), pick.end(), std::size_t{0});
    const std::size_t count = options_.grasps_per_object == 0
                                  ? pick.size()
                                  : std::min(options_.grasps_per_object, pick.size());
    std::vector<lie::Pose> grasps;
    for (std::size_t i = 0; i < count; ++i) {
      std::swap(pick[i], pick[i + rng_.index(pick.size() - i)]);
      grasps.push_back(object.grasps[pick[i]]);
    }
    Eigen::Matrix3d g = Eigen::Matrix3d::Identity();
    if (options_.augmentation == Augmentation::so3) {
      g = lie::random_rotation(rng_);
    } else if (options_.augmentation == Augmentation::z) {
      g = Eigen::AngleAxisd(2.0 * M_PI * rng_.uniform(), Eigen::Vector3d::UnitZ())
              .toRotationMatrix();
    }
    geometry::SurfacePoints cloud = input_cloud(index);
    DistanceSamples queries;
    if (options_.distance_points > 0) {
      queries = near_surface_distances(surfaces_[index], distances_[index],
                                       options_.distance_points, radii_[index], rng_);
    }
    Eigen::Vector3d factors = Eigen::Vector3d::Ones();
    if (options_.stretch > 0) {
      for (int axis = 0; axis < 3; ++axis)
        factors[axis] += options_.stretch * (2.0 * rng_.uniform() - 1.0);
      stretch_object(cloud, grasps, factors);
      // The queries move with the surface and keep their distances: approximate targets, as the
      // stretched grasps' labels are.
      for (Eigen::Vector3d& q : queries.points) q = q.cwiseProduct(factors);
    }
    ObjectSample sample = make_object_sample(cloud, grasps, g, options_.position_scale);
    sample.object = index;
    sample.stretch = factors;
    const NetworkFrame frame{g, sample.centroid, sample.scale};
    for (std::size_t i = 0; i < queries.points.size(); ++i) {
      const Eigen::Vector3d q = frame.to_network(queries.points[i]);
      for (int c = 0; c < 3; ++c) sample.distance_points.push_back(static_cast<float>(q[c]));
      sample.distances.push_back(static_cast<float>(sample.scale * queries.distances[i]));
    }
    step.push_back(std::move(sample));
  }
  return step;
}

std::string TrainingSampler::state() const {
  std::ostringstream out;
  out << cursor_ << ' ' << order_.size();
  for (std::size_t i : order_) out << ' ' << i;
  out << '\n' << rng_.state();
  return out.str();
}

void TrainingSampler::restore(const std::string& text) {
  std::istringstream in(text);
  std::size_t cursor = 0, size = 0;
  in >> cursor >> size;
  std::vector<std::size_t> order(size);
  for (std::size_t& i : order) in >> i;
  const bool valid =
      in && cursor <= size && (size == 0 || size == objects_.size()) &&
      std::all_of(order.begin(), order.end(), [&](std::size_t i) { return i < objects_.size(); });
  if (!valid) throw Error("invalid training sampler state");
  std::string rng_state;
  in.ignore(1);
  std::getline(in, rng_state);
  rng_.restore(rng_state);
  order_ = std::move(order);
  cursor_ = cursor;
}

}  // namespace graspecmf::data
