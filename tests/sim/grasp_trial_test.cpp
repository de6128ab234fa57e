#include "graspecmf/sim/grasp_trial.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "box_object.hpp"
#include "graspecmf/core/error.hpp"
#include "test_support.hpp"

namespace graspecmf::sim {
namespace {

using testing::box_object;
using Vec3 = Eigen::Vector3d;

// Top-down grasp (approach −z) with the pads at height z, fingers closing along world x.
lie::Pose top_down_grasp(double z, double x_offset = 0.0) {
  lie::Pose grasp;
  grasp.R = lie::so3_exp(Vec3(M_PI, 0, 0));  // gripper z → world −z
  grasp.p = Vec3(x_offset, 0, z + 0.1034);
  return grasp;
}

TEST(GraspTrial, HoldsABoxGraspedAcrossItsMiddle) {
  GraspSimulator sim(box_object(), TrialConfig{});
  const TrialResult r = sim.run(top_down_grasp(0.05));
  EXPECT_FALSE(r.unstable);
  EXPECT_TRUE(r.success);
  // The rubber pads are compliant: under the 70 N squeeze each sinks about 1 mm into the box.
  EXPECT_NEAR(r.final_opening, 0.048, 0.001);
  EXPECT_LT(r.shaking_linear, 0.01);
  EXPECT_LT(r.closing_slip, 0.01);
  EXPECT_LT(r.shaking_slip, 0.01);
}

TEST(GraspTrial, FailsWhenTheHandClosesOnAir) {
  GraspSimulator sim(box_object(), TrialConfig{});
  const TrialResult r = sim.run(top_down_grasp(0.05, 0.15));
  EXPECT_FALSE(r.unstable);
  EXPECT_FALSE(r.success);
  EXPECT_LT(r.final_opening, 0.001);
}

TEST(GraspTrial, FailsWhenOnlyTheFingertipsCatchAnEdge) {
  // Pads 3.5 cm beside the box centre: one finger lands on top of the box, nothing is squeezed.
  GraspSimulator sim(box_object(), TrialConfig{});
  EXPECT_FALSE(sim.run(top_down_grasp(0.05, 0.045)).success);
}

TEST(GraspTrial, RepeatedTrialsAreIdentical) {
  GraspSimulator sim(box_object(), TrialConfig{});
  const TrialResult a = sim.run(top_down_grasp(0.05, 0.01));
  sim.run(top_down_grasp(0.05, 0.15));
  const TrialResult b = sim.run(top_down_grasp(0.05, 0.01));
  EXPECT_EQ(a.success, b.success);
  EXPECT_EQ(a.shaking_linear, b.shaking_linear);
  EXPECT_EQ(a.closing_angular, b.closing_angular);
  EXPECT_EQ(a.shaking_slip, b.shaking_slip);
}

TEST(TrialConfig, JsonRoundTripAndValidation) {
  TrialConfig config;
  config.finger_force = 42.0;
  const TrialConfig copy = trial_config_from_json(to_json(config));
  EXPECT_EQ(copy.finger_force, 42.0);
  EXPECT_EQ(to_json(copy), to_json(config));
  EXPECT_THROW(trial_config_from_json(nlohmann::json{{"finger_force", -1.0}}), Error);
  EXPECT_THROW(trial_config_from_json(nlohmann::json{{"no_such_parameter", 1.0}}), Error);
  EXPECT_THROW(trial_config_from_json(nlohmann::json{{"timestep", "fast"}}), Error);
  // A negative pad-normal inset turns the correction off; it must still be finite.
  EXPECT_EQ(trial_config_from_json(nlohmann::json{{"pad_normal_inset", -1.0}}).pad_normal_inset,
            -1.0);
  EXPECT_THROW(trial_config_from_json(nlohmann::json{{"pad_normal_inset", NAN}}), Error);
  // Switches are JSON booleans.
  EXPECT_TRUE(trial_config_from_json(nlohmann::json{{"mujoco_convex", true}}).mujoco_convex);
  EXPECT_FALSE(trial_config_from_json(to_json(TrialConfig{})).mujoco_convex);
  EXPECT_THROW(trial_config_from_json(nlohmann::json{{"mujoco_convex", 1}}), Error);
  // A trial of more than a million steps is refused before it starts.
  graspecmf::testing::expect_error(
      [] {
        trial_config_from_json(nlohmann::json{{"timestep", 1e-9}, {"contact_timeconst", 1e-8}});
      },
      "at most 1000000");
  EXPECT_NO_THROW(
      trial_config_from_json(nlohmann::json{{"timestep", 1e-5}, {"contact_timeconst", 1e-4}}));
}

}  // namespace
}  // namespace graspecmf::sim
