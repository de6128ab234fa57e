#pragma once
// EMD evaluation of a model on objects with known successful grasps (METHOD.md §7, §8): fixed
// seeded clouds, fixed test rotations, n generated against n reference grasps.

#include <cstdint>
#include <string>
#include <vector>

#include "graspecmf/data/dataset.hpp"
#include "graspecmf/train/train_config.hpp"

namespace graspecmf::train {

struct ObjectEvaluation {
  std::string name;
  std::size_t n = 0;        // grasps compared per rotation
  std::vector<double> emd;  // one per rotation
  double mean_emd = 0.0;
};

// The three fixed test rotations (a super-Fibonacci set; none is the identity).
std::vector<Eigen::Matrix3d> test_rotations();
// The first n of a seeded shuffle of the object's successful grasps (all of them if fewer).
std::vector<lie::Pose> reference_grasps(const data::GraspObject& object, std::size_t n,
                                        std::uint64_t seed);
// For each rotation g: the object's seeded cloud and reference grasps rotated by g, n grasps
// sampled from the model for the rotated cloud, and their EMD to the rotated reference.
ObjectEvaluation evaluate_object(const nn::GraspFlowModel& model, const data::GraspObject& object,
                                 const TrainConfig& config,
                                 const std::vector<Eigen::Matrix3d>& rotations, std::size_t n,
                                 const SamplingSettings& settings, std::uint64_t seed);

}  // namespace graspecmf::train
