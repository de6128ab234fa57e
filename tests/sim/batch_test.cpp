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
  // count_successes counts the same trials' successes.
  std::size_t successes = 0;
  for (const TrialResult& r : one) successes += r.success ? 1 : 0;
  const SuccessCount count = count_successes(object, grasps, TrialConfig{}, 2);
  EXPECT_EQ(count.successes, successes);
  EXPECT_EQ(count.trials, grasps.size());
  EXPECT_DOUBLE_EQ(count.rate(), static_cast<double>(successes) / 6.0);
}

}  // namespace
}  // namespace graspecmf::sim
