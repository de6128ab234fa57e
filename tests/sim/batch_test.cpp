#include "graspecmf/sim/batch.hpp"

#include <gtest/gtest.h>

#include "box_object.hpp"
#include "graspecmf/core/error.hpp"

namespace graspecmf::sim {
namespace {

using Vec3 = Eigen::Vector3d;

TEST(RunTrials, SameLabelsOnOneAndTwoThreads) {
  const SceneObject object = testing::box_object();

  std::vector<lie::Pose> grasps;
  for (int i = 0; i < 6; ++i) {
    lie::Pose g;
    g.R = lie::so3_exp(Vec3(M_PI, 0, 0)) * lie::so3_exp(Vec3(0, 0, 0.3 * i));
    g.p = Vec3(0.01 * (i % 3) - 0.01, 0, 0.05 + 0.1034);
    grasps.push_back(g);
  }
  std::size_t calls = 0;
  const auto one =
      run_trials(object, grasps, TrialConfig{}, 1, [&](std::size_t done, std::size_t total) {
        ++calls;
        EXPECT_EQ(total, grasps.size());
        EXPECT_EQ(done, calls);
      });
  const auto two = run_trials(object, grasps, TrialConfig{}, 2);
  EXPECT_EQ(calls, grasps.size());
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].success, two[i].success) << i;
    EXPECT_EQ(one[i].shaking_linear, two[i].shaking_linear) << i;
    EXPECT_EQ(one[i].closing_angular, two[i].closing_angular) << i;
  }
  EXPECT_THROW(run_trials(object, grasps, TrialConfig{}, 0), Error);
}

TEST(GraspOutcomes, CountsSuccessesAndTheGraspsClearOfTheObject) {
  const SceneObject object = testing::box_object();
  const geometry::MeshRayCaster mesh(object.parts[0]);
  // Pads at mid-height around the box (clear), then the palm sunk into its top and a finger
  // pushed into its side (both in collision).
  std::vector<lie::Pose> grasps;
  for (const Vec3& p :
       {Vec3(-0.01, 0, 0.05 + 0.1034), Vec3(0, 0, 0.05 + 0.1034), Vec3(0.01, 0, 0.05 + 0.1034),
        Vec3(0, 0, 0.03 + 0.1034), Vec3(0.03, 0, 0.05 + 0.1034)}) {
    lie::Pose g;
    g.R = lie::so3_exp(Vec3(M_PI, 0, 0));
    g.p = p;
    grasps.push_back(g);
  }
  const std::vector<TrialResult> results = run_trials(object, grasps, TrialConfig{}, 1);
  const GraspOutcomes outcomes = grasp_outcomes(object, mesh, grasps, TrialConfig{}, 2);
  std::size_t successes = 0, clear_successes = 0;
  for (std::size_t i = 0; i < results.size(); ++i) {
    successes += results[i].success ? 1 : 0;
    clear_successes += i < 3 && results[i].success ? 1 : 0;
  }
  EXPECT_EQ(outcomes.all.trials, 5U);
  EXPECT_EQ(outcomes.all.successes, successes);
  EXPECT_EQ(outcomes.collision_free.trials, 3U);
  EXPECT_EQ(outcomes.collision_free.successes, clear_successes);
  EXPECT_GT(clear_successes, 0U);
  EXPECT_DOUBLE_EQ(outcomes.collision_rate(), 0.4);
  GraspOutcomes twice = outcomes;
  twice += outcomes;
  EXPECT_EQ(twice.all.trials, 10U);
  EXPECT_EQ(twice.collision_free.successes, 2 * clear_successes);
  EXPECT_DOUBLE_EQ(GraspOutcomes{}.collision_rate(), 0.0);
}

}  // namespace
}  // namespace graspecmf::sim
