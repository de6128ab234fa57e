#pragma once
// EMD evaluation of a model on objects with known successful grasps (docs/method.md, "Evaluation:
// the EMD"): fixed seeded clouds, fixed test rotations, n generated against n reference grasps.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "graspecmf/camera/partial_view.hpp"
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
  double sampling_seconds = 0.0;      // wall time drawing the grasps, all rotations together
  std::optional<std::size_t> passed;  // with a filter: the generated grasps it kept, all rotations
  // The n generated grasps of each rotation, rotated back into the object's frame.
  std::vector<std::vector<lie::Pose>> generated;
  std::vector<camera::ViewDraw> views;  // each rotation's camera, when the input is views
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

// What the model is given of each test object: its whole surface (the paper), or per rotation one
// random camera's view of it as it stands on a table at its lowest z (camera::partial_cloud: the
// camera is drawn in the object's frame and the view rotated with the object); and whether the
// grasps must stay above that table (the filter's support plane, rotated likewise).
struct InputSetting {
  std::optional<camera::ViewSampling> views;
  bool table = false;
};
// "full" or "views", with " above the table" when input.table.
std::string to_string(const InputSetting& input);

// For each rotation g: the object's seeded cloud (or view) and reference grasps rotated by g, n
// grasps sampled from the model for the rotated cloud (with checks or a table, ones that the
// filter, rotated by g, keeps, made up with rejected ones under settings.fill_rejected), and their
// EMD to the rotated reference; the generated grasps are kept, in the object's frame.
ObjectEvaluation evaluate_object(const models::GeneratorImpl& model,
                                 const data::GraspObject& object, const models::TrainConfig& config,
                                 const std::vector<Eigen::Matrix3d>& rotations, std::size_t n,
                                 const models::SamplingSettings& settings, std::uint64_t seed,
                                 const ObjectFilter& filter = {}, const InputSetting& input = {});

struct BaselineEvaluation {
  std::size_t n = 0;      // grasps compared
  BaselineScores scores;  // random grasps, the nearest training object, the sampling floor
  std::vector<lie::Pose> nearest_grasps;  // the nearest object's grasps, moved onto this object
};

// The training objects with their seeded surface clouds centred on their centroids, computed once
// so that the nearest-object baseline of a whole test split samples each training cloud once.
class TrainingShapes {
 public:
  // Keeps a reference to `objects`, which must outlive this. Throws Error if it is empty. With
  // views, nearest_to_view can also render the training objects.
  TrainingShapes(const std::vector<data::GraspObject>& objects, std::uint64_t seed,
                 const std::optional<camera::ViewSampling>& views = std::nullopt);
  // The training object whose centred cloud is closest (Chamfer) to `object`'s, and its centroid;
  // one with `object`'s own name is passed over (leave-one-out, for evaluating the train split).
  // Throws Error if no other training object exists.
  const data::GraspObject& nearest(const data::GraspObject& object, Eigen::Vector3d& centroid,
                                   Eigen::Vector3d& nearest_centroid) const;
  // The same given only one view of `object`: the training object whose view from the same
  // camera (relative to its own bounding box) is closest to this one's, both centred; centroids
  // are the views'. Throws Error without views or another training object.
  const data::GraspObject& nearest_to_view(const data::GraspObject& object,
                                           const camera::ViewDraw& view, Eigen::Vector3d& centroid,
                                           Eigen::Vector3d& nearest_centroid) const;

 private:
  // The training object (not named `name`) whose cloud is closest to `cloud`; both centred.
  std::size_t closest(const std::vector<Eigen::Vector3d>& cloud, const std::string& name,
                      const std::function<std::vector<Eigen::Vector3d>(std::size_t)>& other) const;

  const std::vector<data::GraspObject>& objects_;
  std::uint64_t seed_;
  std::optional<camera::ViewSampling> views_;
  std::vector<geometry::MeshRayCaster> casters_;  // with views only
  std::vector<std::vector<Eigen::Vector3d>> clouds_;
  std::vector<Eigen::Vector3d> centroids_;
};

// The two reference baselines of issue 5, in the object's own frame (a common rotation leaves the
// EMD unchanged, so one value stands for every test rotation): n grasps with Haar-random rotations
// and positions uniform in the object's bounding box grown by the pad-centre distance (grasp
// frames sit that far from the surface); and the successful grasps of the other training object
// with the smallest Chamfer distance between centred seeded clouds (with checks, only those that
// the object's filter keeps). Also the sampling floor. With input.views, the nearest object is
// found from `view` (TrainingShapes::nearest_to_view; required then); with input.table, its grasps
// must also stay above the table.
BaselineEvaluation evaluate_baselines(const data::GraspObject& object,
                                      const TrainingShapes& training, std::size_t n,
                                      std::uint64_t seed, const ObjectFilter& filter = {},
                                      const InputSetting& input = {},
                                      const camera::ViewDraw* view = nullptr);

}  // namespace graspecmf::eval
