#pragma once
// Agreement of simulated grasp labels with reference labels (e.g. ACRONYM's object_in_gripper):
// accuracy, confusion matrix, and the best single threshold on the recorded shaking motion.

#include <cstdint>
#include <vector>

#include "graspecmf/sim/grasp_trial.hpp"

namespace graspecmf::sim {

struct LabelAgreement {
  std::size_t count = 0;
  // Confusion matrix: reference label × simulated label.
  std::size_t both_success = 0, both_failure = 0;
  std::size_t only_reference_success = 0;  // reference success, simulated failure
  std::size_t only_simulated_success = 0;  // reference failure, simulated success
  double accuracy = 0.0;
  // Labelling "success iff shaking_linear < threshold" agrees best with the reference at this
  // threshold (unstable trials count as failures), with this accuracy.
  double best_shaking_threshold = 0.0;
  double best_threshold_accuracy = 0.0;
};

// Throws Error if the lengths differ or there are no results.
LabelAgreement compare_labels(const std::vector<TrialResult>& results,
                              const std::vector<std::int64_t>& reference);

}  // namespace graspecmf::sim
