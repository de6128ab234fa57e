#pragma once
// Labelling many grasps of one object on several threads (one MuJoCo model + data per thread).
// Results do not depend on the thread count: every trial starts from a reset state.

#include <functional>
#include <vector>

#include "graspecmf/data/acronym_file.hpp"
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

// Runs a trial per grasp (in the object's frame) like run_trials and counts the successes;
// unstable trials count as failures.
SuccessCount count_successes(const SceneObject& object, const std::vector<lie::Pose>& grasps,
                             const TrialConfig& config, int threads);

// ACRONYM's quality arrays for the results: object_in_gripper (1 = success) and the closing and
// shaking motion integrals, in result order.
data::GraspQualities acronym_qualities(const std::vector<TrialResult>& results);

}  // namespace graspecmf::sim
