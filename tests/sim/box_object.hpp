#pragma once
// The simulated object of the sim unit tests: a 5 × 5 × 8 cm box of 150 kg/m³ centred at
// (0, 0, 0.04), as one convex part.

#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/oriented_box.hpp"
#include "graspecmf/sim/grasp_scene.hpp"

namespace graspecmf::sim::testing {

inline SceneObject box_object() {
  geometry::OrientedBox box;
  box.pose.p = Eigen::Vector3d(0, 0, 0.04);
  box.half_extents = Eigen::Vector3d(0.025, 0.025, 0.04);
  SceneObject object;
  object.parts = {geometry::box_mesh(box)};
  const geometry::MassProperties mp = geometry::mass_properties(object.parts[0], 150.0);
  object.mass = mp.mass;
  object.center_of_mass = mp.center_of_mass;
  object.inertia = mp.inertia;
  return object;
}

}  // namespace graspecmf::sim::testing
