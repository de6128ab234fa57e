#pragma once
// Every parameter of the grasp shake test (METHOD.md §9), with physically sensible defaults; the
// whole struct is written beside any results it produced.

#include <nlohmann/json_fwd.hpp>

namespace graspecmf::sim {

struct TrialConfig {
  // Physics.
  double timestep = 0.002;  // s
  double gravity = 9.81;    // m/s², along −z of the world (object) frame
  double friction = 1.0;    // sliding friction, object and fingers (ACRONYM: 1.0)
  double torsional_friction = 0.005;
  double contact_timeconst = 0.004;  // s, contact stiffness (MuJoCo solref; ≥ 2 × timestep)
  double default_density = 150;      // kg/m³, when the grasp file has no mass (ACRONYM: 150)
  // Hand: a free body welded softly to a moving target, fingers on force-limited slides.
  double hand_mass = 0.73;      // kg, Franka hand
  double finger_mass = 0.015;   // kg each
  double finger_force = 70.0;   // N per finger (Franka hand: 70 N continuous)
  double finger_gain = 2000.0;  // N/m position gain of the finger servo
  double finger_damping = 5.0;  // N·s/m on the finger slides
  // Phases (steps = duration / timestep).
  double close_duration = 0.4;            // s, gravity off while the fingers close
  double settle_duration = 0.1;           // s, gravity on, hand still
  double lift_distance = 0.05;            // m, along −approach (away from the object)
  double lift_duration = 0.3;             // s
  double shake_linear_amplitude = 0.02;   // m, along the approach axis
  double shake_angular_amplitude = 0.35;  // rad, about the gripper y axis
  double shake_frequency = 2.0;           // Hz
  double shake_cycles = 2.0;
  // Judgement: success = object touches both fingers and moved less than this relative to the
  // hand between the end of closing and the end of shaking.
  double max_relative_translation = 0.02;  // m
  double max_relative_rotation = 0.5;      // rad
};

// Throws Error naming the first parameter that is out of range.
void validate(const TrialConfig& config);
nlohmann::json to_json(const TrialConfig& config);
// Reads a config (missing keys keep their defaults; unknown keys are an Error).
TrialConfig trial_config_from_json(const nlohmann::json& json);

}  // namespace graspecmf::sim
