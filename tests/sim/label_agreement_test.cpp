#include "graspecmf/sim/label_agreement.hpp"

#include <gtest/gtest.h>

#include "graspecmf/core/error.hpp"

namespace graspecmf::sim {
namespace {

TrialResult trial(bool success, double shaking, bool unstable = false) {
  TrialResult r;
  r.success = success;
  r.shaking_linear = shaking;
  r.unstable = unstable;
  return r;
}

TEST(LabelAgreement, ConfusionMatrixAndAccuracy) {
  const std::vector<TrialResult> sim = {trial(true, 0.001), trial(true, 0.002), trial(false, 0.05),
                                        trial(false, 0.3, true), trial(true, 0.004)};
  const LabelAgreement a = compare_labels(sim, {1, 0, 0, 1, 1});
  EXPECT_EQ(a.count, 5u);
  EXPECT_EQ(a.both_success, 2u);
  EXPECT_EQ(a.both_failure, 1u);
  EXPECT_EQ(a.only_simulated_success, 1u);
  EXPECT_EQ(a.only_reference_success, 1u);
  EXPECT_DOUBLE_EQ(a.accuracy, 0.6);
}

TEST(LabelAgreement, BestThresholdSeparatesTheMotions) {
  // Reference successes have motions 0.001, 0.003, 0.004; failures 0.002, 0.02, 0.05 and one
  // unstable trial. The best threshold passes the first four (one error) and no more.
  const std::vector<TrialResult> sim = {
      trial(false, 0.001), trial(false, 0.002), trial(false, 0.003),    trial(false, 0.004),
      trial(false, 0.02),  trial(false, 0.05),  trial(false, 0.0, true)};
  const LabelAgreement a = compare_labels(sim, {1, 0, 1, 1, 0, 0, 0});
  EXPECT_NEAR(a.best_shaking_threshold, 0.012, 1e-12);
  EXPECT_NEAR(a.best_threshold_accuracy, 6.0 / 7.0, 1e-12);
}

TEST(LabelAgreement, RejectsMismatchedLengths) {
  EXPECT_THROW(compare_labels({trial(true, 0)}, {1, 0}), Error);
  EXPECT_THROW(compare_labels({}, {}), Error);
}

}  // namespace
}  // namespace graspecmf::sim
