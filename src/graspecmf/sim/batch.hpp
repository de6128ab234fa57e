#pragma once
// Labelling many grasps of one object on several threads (one MuJoCo model + data per thread).
// Results do not depend on the thread count: every trial starts from a reset state.

#include <functional>
#include <vector>

#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/ray_cast.hpp"
#include "graspecmf/sim/grasp_trial.hpp"

namespace graspecmf::sim {

// Called after each finished trial with (finished, total), from one thread at a time.
using ProgressCallback = std::function<void(std::size_t finished, std::size_t total)>;

// Runs a trial per grasp on `threads` threads (≥ 1); results are in grasp order.
std::vector<TrialResult> run_trials(const SceneObject& object, const std::vector<lie::Pose>& grasps,
                                    const TrialConfig& config, int threads,
                                    const ProgressCallback& progress = {});

// Successful trials among some trials; rate() is 0 when there are none.
struct SuccessCount {
  std::size_t successes = 0;
  std::size_t trials = 0;
  double rate() const {
    return trials == 0 ? 0.0 : static_cast<double>(successes) / static_cast<double>(trials);
  }
  SuccessCount& operator+=(const SuccessCount& other) {
    successes += other.successes;
    trials += other.trials;
    return *this;
  }
};

// Trials of some grasps, and the part of them whose open hand starts clear of the object.
struct GraspOutcomes {
  SuccessCount all;             // every trial; unstable ones count as failures
  SuccessCount collision_free;  // the trials whose open hand does not intersect the object mesh
  // Fraction of the trials whose open hand intersects the object; 0 when there are none.
  double collision_rate() const {
    return all.trials == 0
               ? 0.0
               : 1.0 - static_cast<double>(collision_free.trials) / static_cast<double>(all.trials);
  }
  GraspOutcomes& operator+=(const GraspOutcomes& other) {
    all += other.all;
    collision_free += other.collision_free;
    return *this;
  }
};

// Runs a trial per grasp (in the object's frame) like run_trials and counts the successes, also
// among the grasps whose fully open hand is clear of `mesh` (the object's closed mesh;
// gripper::in_collision).
GraspOutcomes grasp_outcomes(const SceneObject& object, const geometry::MeshRayCaster& mesh,
                             const std::vector<lie::Pose>& grasps, const TrialConfig& config,
                             int threads);

// ACRONYM's quality arrays for the results: object_in_gripper (1 = success) and the closing and
// shaking motion integrals, in result order.
data::GraspQualities acronym_qualities(const std::vector<TrialResult>& results);

}  // namespace graspecmf::sim
