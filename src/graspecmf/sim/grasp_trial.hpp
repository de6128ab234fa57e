#pragma once
// One MuJoCo model + data for an object, running grasp trials: place the open hand at the grasp,
// close, lift and shake, then judge (docs/simulator.md). Not thread-safe: use one per thread.

#include <memory>

#include "graspecmf/lie/se3.hpp"
#include "graspecmf/sim/grasp_scene.hpp"

namespace graspecmf::sim {

struct TrialResult {
  bool success = false;
  bool unstable = false;  // NaN or a MuJoCo warning: counted as a failure
  // ACRONYM-style integrals of the object's motion relative to the hand (metres, radians).
  double closing_linear = 0.0, closing_angular = 0.0;
  double shaking_linear = 0.0, shaking_angular = 0.0;
  // Path length, relative to the hand, of the object point that sat at the finger-pad centre at
  // the start of the phase: a pivot about the closing axis through the pads does not count.
  double closing_slip = 0.0, shaking_slip = 0.0;
  double final_opening = 0.0;  // distance between the finger pads at the end, m
};

class GraspSimulator {
 public:
  // Compiles the scene; throws Error if MuJoCo rejects it.
  GraspSimulator(const SceneObject& object, const TrialConfig& config);
  ~GraspSimulator();
  GraspSimulator(const GraspSimulator&) = delete;
  GraspSimulator& operator=(const GraspSimulator&) = delete;

  // Runs one trial for the grasp T_object_gripper; deterministic for a given grasp.
  TrialResult run(const lie::Pose& grasp);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace graspecmf::sim
