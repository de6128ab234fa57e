#pragma once
// A coloured line segment of a scene, e.g. part of a grasp's gripper marker; drawn by both the
// software renderer (render.hpp) and the HTML view (html_view.hpp).

#include <array>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::viz {

struct Segment {
  geometry::Vec3 a, b;
  std::array<int, 3> rgb;  // 0–255
};

}  // namespace graspecmf::viz
