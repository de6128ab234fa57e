#pragma once
// What one training step sees (docs/method.md, "Flow matching on SO(3) × R³"): a few objects, each
// with a fresh point cloud (of its whole surface, or of what one random camera sees of it) and a
// subset of its successful grasps, rotated by the
// augmentation, centred on the cloud's centroid and scaled by the network's position scale.
// Torch-free: plain float arrays.

#include <cstdint>
#include <string>
#include <vector>

#include "graspecmf/camera/partial_view.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/data/dataset.hpp"
#include "graspecmf/geometry/surface_sampling.hpp"
#include "graspecmf/geometry/unsigned_distance.hpp"

namespace graspecmf::data {

// The paper's augmentation settings: none, a random rotation about the world z axis, or a
// Haar-uniform random rotation.
enum class Augmentation { none, z, so3 };
// "none", "z" or "so3" → the setting; throws Error for another name.
Augmentation parse_augmentation(const std::string& name);
std::string to_string(Augmentation augmentation);

// The input clouds: the object's whole surface, what one random camera above it sees
// (camera::partial_cloud), or either with equal odds.
enum class CloudInput { full, partial, mixed };
// "full", "partial" or "mixed" → the setting; throws Error for another name.
CloudInput parse_cloud_input(const std::string& name);
std::string to_string(CloudInput input);

// One object in network units: x_net = scale · (g x − c), with g the augmentation rotation and c
// the centroid of the rotated cloud.
struct ObjectSample {
  std::size_t object = 0;                                  // index into the sampler's objects
  std::vector<float> points;                               // N × 3
  std::vector<float> rotations;                            // G × 9, row-major R
  std::vector<float> positions;                            // G × 3
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // g
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();      // c, metres, after the rotation
  double scale = 1.0;
  Eigen::Vector3d stretch = Eigen::Vector3d::Ones();  // shape augmentation factors, object frame
  std::vector<float> distance_points;  // K × 3 queries near the surface, network units
  std::vector<float> distances;        // their K unsigned distances to the surface, network units
};

struct TrainingSamplerOptions {
  std::size_t objects_per_step = 4;
  std::size_t grasps_per_object = 300;  // drawn without replacement; 0 or more than available = all
  std::size_t points = 1024;
  double position_scale = 8.0;
  Augmentation augmentation = Augmentation::so3;
  // Shape augmentation: before the rotation, each object is stretched along its own x, y and z
  // axes by factors drawn uniformly from [1 − stretch, 1 + stretch]; 0 turns it off.
  double stretch = 0.0;
  // Distance-field targets (SE(3)-DiF's auxiliary loss): query points near the surface per object
  // with their unsigned distances to it; 0 draws none.
  std::size_t distance_points = 0;
  // Partial views come from `views`; each gives `points` of its points (drawn without
  // replacement, or every point and then repeats when it has fewer).
  CloudInput input = CloudInput::full;
  camera::ViewSampling views;
};

// Stretches a sampled object by S = diag(factors) in its own frame: points q → S q (normals
// follow S⁻¹), and each grasp keeps its orientation while its finger-pad centre c moves to S c.
// Approximate labels for a slightly different shape: a stretched surface's normals tilt.
void stretch_object(geometry::SurfacePoints& cloud, std::vector<lie::Pose>& grasps,
                    const Eigen::Vector3d& factors);

// Query points near a surface and their unsigned distances to it, metres.
struct DistanceSamples {
  std::vector<Eigen::Vector3d> points;
  std::vector<double> distances;
};
// count surface points each moved by an isotropic Gaussian offset, of standard deviation
// 0.05 · radius for the even-numbered and 0.0158 · radius for the odd-numbered ones (the offsets
// of the mesh_to_sdf library's near-surface sampling for a mesh of that bounding radius).
DistanceSamples near_surface_distances(const geometry::SurfaceSampler& surface,
                                       const geometry::UnsignedDistance& distance,
                                       std::size_t count, double radius, Rng& rng);

// The cloud of `points` surface points of mesh, rotated by g, centred and scaled; grasps likewise.
ObjectSample make_object_sample(const geometry::SurfacePoints& cloud,
                                const std::vector<lie::Pose>& grasps, const Eigen::Matrix3d& g,
                                double position_scale);

class TrainingSampler {
 public:
  // Throws Error if there are no objects, an object has no grasps, or an option is zero.
  TrainingSampler(std::vector<GraspObject> objects, const TrainingSamplerOptions& options,
                  std::uint64_t seed);
  TrainingSampler(const TrainingSampler&) = delete;  // the surface samplers refer to objects_
  TrainingSampler& operator=(const TrainingSampler&) = delete;
  // The next step's objects: epochs visit every object once in a fresh shuffled order.
  std::vector<ObjectSample> next_step();
  const std::vector<GraspObject>& objects() const { return objects_; }
  // Complete state as text (generator, epoch order, position); restore continues identically.
  std::string state() const;
  void restore(const std::string& text);

 private:
  // The step's cloud of object `index`: its surface, or a partial view, as options_.input says.
  geometry::SurfacePoints input_cloud(std::size_t index);

  std::vector<GraspObject> objects_;
  std::vector<geometry::SurfaceSampler> surfaces_;
  std::vector<geometry::UnsignedDistance> distances_;  // only when options_.distance_points > 0
  std::vector<geometry::MeshRayCaster> casters_;       // only when the input can be partial
  std::vector<double> radii_;                          // half the bounding-box diagonals
  TrainingSamplerOptions options_;
  Rng rng_;
  std::vector<std::size_t> order_;
  std::size_t cursor_ = 0;
};

}  // namespace graspecmf::data
