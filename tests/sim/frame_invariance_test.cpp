// The shake test must not depend on where the object sits: the sample mug and its grasps moved
// together by metres and turned about the gravity axis get the same labels (a subset of 100 of its
// 2000 grasps; all 2000 are measured with `graspecmf simulate --move`, docs/simulator.md).

#include <gtest/gtest.h>

#include <vector>

#include "graspecmf/sim/batch.hpp"
#include "sample_mug.hpp"

namespace graspecmf::sim {
namespace {

constexpr std::size_t kStride = 20;

std::vector<TrialResult> moved_labels(const lie::Pose& motion, const TrialConfig& config) {
  const testing::SampleMug mug = testing::sample_mug(kStride, config, motion);
  return run_trials(mug.object, mug.grasps, config, 2);
}

lie::Pose far_and_turned() {
  lie::Pose motion;
  motion.R = Eigen::AngleAxisd(0.65, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  motion.p = Eigen::Vector3d(2.7, 1.2, 0.0);
  return motion;
}

// The simulation frame sits at the centre of mass and turns with the object about gravity.
TEST(FrameInvariance, SimulationFrameMovesWithTheObject) {
  const lie::Pose motion = far_and_turned();
  const lie::Pose here = simulation_frame(testing::sample_mug(kStride).object, {});
  const lie::Pose there = simulation_frame(testing::sample_mug(kStride, {}, motion).object, {});
  const lie::Pose expected = lie::compose(motion, here);
  EXPECT_LT((there.R - expected.R).norm(), 1e-9);
  EXPECT_LT((there.p - expected.p).norm(), 1e-9);
  EXPECT_EQ(here.R.col(2), Eigen::Vector3d::UnitZ());
}

std::size_t same_labels(const std::vector<TrialResult>& a, const std::vector<TrialResult>& b) {
  std::size_t same = 0;
  for (std::size_t i = 0; i < a.size(); ++i) same += a[i].success == b[i].success;
  return same;
}

TEST(FrameInvariance, MovedAndTurnedMugKeepsItsLabels) {
  const std::vector<TrialResult> here = moved_labels(lie::Pose{}, TrialConfig{});
  const std::vector<TrialResult> there = moved_labels(far_and_turned(), TrialConfig{});
  ASSERT_EQ(here.size(), 100u);
  // The trial's inputs are quantised in the simulation frame, so the trials are the same to the
  // last bit (but where a coordinate straddles a quantisation step, which is rare).
  EXPECT_GE(same_labels(here, there), 99u);
  std::size_t identical = 0;
  for (std::size_t i = 0; i < here.size(); ++i) {
    identical += here[i].shaking_linear == there[i].shaking_linear &&
                 here[i].closing_angular == there[i].closing_angular;
  }
  EXPECT_GE(identical, 99u);
}

// Datasets made before 2026-12-04 (legacy_object_frame) were simulated in the mesh frame: with the
// mesh origin metres from the object, MuJoCo integrates the free object there, and most held grasps
// fail.
TEST(FrameInvariance, LegacyObjectFrameDependsOnWhereTheMugSits) {
  TrialConfig legacy;
  legacy.legacy_object_frame = true;
  const std::vector<TrialResult> here = moved_labels(lie::Pose{}, legacy);
  const std::vector<TrialResult> there = moved_labels(far_and_turned(), legacy);
  EXPECT_LT(same_labels(here, there), 80u);
}

}  // namespace
}  // namespace graspecmf::sim
