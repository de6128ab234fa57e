#pragma once
// Finger-pad contact normals. MuJoCo collides a finger with an object part by MPR, which returns
// one direction of least penetration for the two convex shapes. When a round object presses into
// the pad near its edge (the compliant contacts let it sink ~1 mm), that direction tips towards
// the edge and the squeeze pushes the object out of the hand. A point inside a flat face can only
// be pushed along the face's normal, so contacts well inside the pad get the pad's normal.

struct mjModel_;
struct mjData_;
struct mjContact_;

namespace graspecmf::sim {

class PadContactNormals {
 public:
  // For the grasp scene's two fingers (sim/grasp_scene.hpp); contacts at least `inset` metres
  // inside the pad's edges (gripper::panda pad bounds) are corrected. Throws Error if the model
  // lacks the finger bodies or inset is negative.
  PadContactNormals(const mjModel_* model, double inset);

  // Gives each of the `count` contacts of pair (g1, g2) that lies on a finger pad, at least
  // `inset` inside its edges and within 5 mm of its plane, the pad's normal (keeping the contact's
  // orientation sign) and a fresh tangent frame. Pairs without a finger are left alone.
  void correct(const mjModel_* model, const mjData_* data, mjContact_* contacts, int count, int g1,
               int g2) const;

 private:
  int left_body_, right_body_;
  double inset_;
};

}  // namespace graspecmf::sim
