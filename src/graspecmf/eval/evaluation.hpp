#pragma once
// EMD evaluation of a model on objects with known successful grasps (docs/method.md, "Evaluation:
// the EMD"): fixed seeded clouds, fixed test rotations, n generated against n reference grasps.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "graspecmf/data/dataset.hpp"
#include "graspecmf/eval/report.hpp"
#include "graspecmf/gripper/cloud_grasp_filter.hpp"
#include "graspecmf/models/generator.hpp"
#include "graspecmf/models/train_config.hpp"

namespace graspecmf::eval {

struct ObjectEvaluation {
  std::string name;
  std::size_t n = 0;        // grasps compared per rotation
  std::vector<double> emd;  // one per rotation
  double mean_emd = 0.0;
  double sampling_seconds = 0.0;  // wall time drawing the grasps, all rotations together
  // The n generated grasps of each rotation, rotated back into the object's frame.
  std::vector<std::vector<lie::Pose>> generated;
};

// The three fixed test rotations (a super-Fibonacci set; none is the identity).
std::vector<Eigen::Matrix3d> test_rotations();
// The object's successful grasps in a seeded shuffle.
std::vector<lie::Pose> shuffled_grasps(const data::GraspObject& object, std::uint64_t seed);
// The first n of shuffled_grasps (all of them if fewer).
std::vector<lie::Pose> reference_grasps(const data::GraspObject& object, std::size_t n,
                                        std::uint64_t seed);
// Grasp checks on one object and the cloud they run on, in the object's frame.
struct ObjectFilter {
  gripper::GraspChecks checks;
  // gripper::filter_cloud of the object's mesh; empty if no check is on.
  std::vector<Eigen::Vector3d> points;
};
// The object's filter for these checks, its cloud drawn with the seed (drawn once per object and
// shared by the model's and the baselines' evaluation).
ObjectFilter object_filter(const data::GraspObject& object, const gripper::GraspChecks& checks,
                           std::uint64_t seed);

// For each rotation g: the object's seeded cloud and reference grasps rotated by g, n grasps
// sampled from the model for the rotated cloud (with checks, only ones that the filter, rotated by
// g, keeps), and their EMD to the rotated reference; the generated grasps are kept, in the
// object's frame.
ObjectEvaluation evaluate_object(const models::GeneratorImpl& model,
                                 const data::GraspObject& object, const models::TrainConfig& config,
                                 const std::vector<Eigen::Matrix3d>& rotations, std::size_t n,
                                 const models::SamplingSettings& settings, std::uint64_t seed,
                                 const ObjectFilter& filter = {});

struct BaselineEvaluation {
  std::size_t n = 0;      // grasps compared
  BaselineScores scores;  // random grasps, the nearest training object, the sampling floor
  std::vector<lie::Pose> nearest_grasps;  // the nearest object's grasps, moved onto this object
};

// The training objects with their seeded surface clouds centred on their centroids, computed once
// so that the nearest-object baseline of a whole test split samples each training cloud once.
class TrainingShapes {
 public:
  // Keeps a reference to `objects`, which must outlive this. Throws Error if it is empty.
  TrainingShapes(const std::vector<data::GraspObject>& objects, std::uint64_t seed);
  // The training object whose centred cloud is closest (Chamfer) to `object`'s, and its centroid;
  // one with `object`'s own name is passed over (leave-one-out, for evaluating the train split).
  // Throws Error if no other training object exists.
  const data::GraspObject& nearest(const data::GraspObject& object, Eigen::Vector3d& centroid,
                                   Eigen::Vector3d& nearest_centroid) const;

 private:
  const std::vector<data::GraspObject>& objects_;
  std::uint64_t seed_;
  std::vector<std::vector<Eigen::Vector3d>> clouds_;
  std::vector<Eigen::Vector3d> centroids_;
};

// The two reference baselines of issue 5, in the object's own frame (a common rotation leaves the
// EMD unchanged, so one value stands for every test rotation): n grasps with Haar-random rotations
// and positions uniform in the object's bounding box grown by the pad-centre distance (grasp
// frames sit that far from the surface); and the successful grasps of the other training object
// with the smallest Chamfer distance between centred seeded clouds (with checks, only those that
// the object's filter keeps). Also the sampling floor.
BaselineEvaluation evaluate_baselines(const data::GraspObject& object,
                                      const TrainingShapes& training, std::size_t n,
                                      std::uint64_t seed, const ObjectFilter& filter = {});

}  // namespace graspecmf::eval
