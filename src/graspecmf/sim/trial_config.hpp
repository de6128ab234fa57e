#pragma once
// Every parameter of the grasp shake test (docs/simulator.md), with physically sensible defaults;
// the whole struct is written beside any results it produced.

#include <nlohmann/json_fwd.hpp>
#include <string>

namespace graspecmf::sim {

struct TrialConfig {
  // Physics.
  double timestep = 0.002;  // s
  double gravity = 9.81;    // m/s², along −z of the world (object) frame
  double friction = 1.0;    // sliding friction, object and fingers (ACRONYM's value)
  // MuJoCo's impratio: frictional over normal constraint impedance. Below 10 the friction
  // constraint is softer, so a sustained sideways push creeps (tuned; see docs/simulator.md).
  double friction_impedance_ratio = 4.0;
  double torsional_friction = 0.005;  // m, torsional friction (MuJoCo condim 4)
  // Contact compliance (MuJoCo solref/solimp): the finger pads are rubber, so contacts are soft.
  double contact_timeconst = 0.004;  // s, contact stiffness (solref; ≥ 2 × timestep)
  // MuJoCo's contact stiffness is per unit of mass (solref is a time constant), so a fixed
  // contact_timeconst makes a heavier object's pads stiffer in newtons per metre. With a positive
  // reference mass (kg), an object of mass m gets contact_timeconst × √(m / reference), at least
  // 2 × timestep: the pads keep the force stiffness they have on an object of the reference mass,
  // the ACRONYM sample mug they were tuned on. 0: contact_timeconst for every object.
  double contact_reference_mass = 0.0130879738;
  double contact_dmin = 0.95;    // solimp impedance at zero penetration, in (0, 1)
  double contact_dmax = 0.99;    // solimp impedance at contact_width penetration, in (0, 1)
  double contact_width = 0.002;  // m, penetration over which the impedance ramps up
  // A finger–object contact whose point lies on a finger's flat pad at least this far (m) inside
  // its edges is pushed along the pad's normal (sim/pad_contact_normals.hpp); negative: off, all
  // normals are MuJoCo's.
  double pad_normal_inset = 0.00225;
  // Convex pairs (mesh–mesh, box–mesh): false, sim::ConvexNarrowPhase (MuJoCo's algorithm, ~1.3×
  // faster trials, contacts equal up to round-off and the extra contacts' tilt axes); true,
  // MuJoCo's own function, as datasets labelled before 2026-12-02 were.
  bool mujoco_convex = false;
  // false (default): the trial does not depend on where the object sits. It is simulated in a
  // frame at the object's centre of mass turned to its horizontal principal axis
  // (sim::simulation_frame), and the convex decomposition is cut in the solid's principal frame
  // (geometry::principal_frame). true: as datasets labelled before 2026-12-04, in the mesh frame,
  // where a far mesh origin corrupts the free object's motion and labels change when the object
  // and its grasps move together (docs/simulator.md, "Frame invariance").
  bool legacy_object_frame = false;
  double default_density = 150;  // kg/m³, when the grasp file has no mass (ACRONYM: 150)
  // Hand: a free body welded softly to a moving target, fingers on force-limited slides.
  double hand_mass = 0.73;       // kg, Franka hand
  double finger_mass = 0.015;    // kg each
  double finger_force = 70.0;    // N per finger (Franka hand: 70 N continuous)
  double finger_gain = 2000.0;   // N/m position gain of the finger servo
  double finger_damping = 50.0;  // N·s/m on the finger slides
  double finger_armature = 1.0;  // kg, the finger drive's reflected inertia (spindle + motor)
  // Phases (steps = duration / timestep).
  double close_duration = 1.0;            // s, gravity off while the fingers close
  double settle_duration = 0.1;           // s, gravity on, hand still
  double lift_distance = 0.05;            // m, along −approach (away from the object)
  double lift_duration = 0.3;             // s
  double shake_linear_amplitude = 0.02;   // m, along the approach axis
  double shake_angular_amplitude = 0.35;  // rad, about the gripper y axis
  double shake_frequency = 2.0;           // Hz
  double shake_cycles = 2.0;
  // Judgement: success = object touches both fingers and moved less than this relative to the
  // hand between the end of closing and the end of shaking.
  double max_relative_translation = 0.05;  // m
  double max_relative_rotation = 1.5;      // rad
};

// Throws Error naming the first parameter that is out of range.
void validate(const TrialConfig& config);
nlohmann::json to_json(const TrialConfig& config);
// Reads a config (missing keys keep their defaults; unknown keys are an Error).
TrialConfig trial_config_from_json(const nlohmann::json& json);
// A config file's JSON object, not yet applied; an empty path gives {}. Throws Error naming the
// file if it cannot be read or parsed, or is not an object.
nlohmann::json read_trial_config_json(const std::string& path);
// Reads a config file (JSON, as trial_config_from_json); an empty path gives the defaults.
TrialConfig read_trial_config(const std::string& path);

}  // namespace graspecmf::sim
