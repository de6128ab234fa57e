#pragma once
// Depth images of an object standing on a table, rendered exactly by casting one ray per pixel
// centre against the object's mesh and the table's plane, with the object's mask.

#include <cstdint>
#include <optional>
#include <vector>

#include "graspecmf/camera/depth_image.hpp"
#include "graspecmf/camera/intrinsics.hpp"
#include "graspecmf/geometry/plane_fit.hpp"
#include "graspecmf/geometry/ray_cast.hpp"
#include "graspecmf/lie/se3.hpp"

namespace graspecmf::camera {

// What a camera sees of the scene.
struct RenderedView {
  DepthImage depth;                       // metres along the viewing axis; 0 where nothing is hit
  std::vector<std::uint8_t> object_mask;  // 1 where the pixel sees the object
  std::vector<float> incidence;  // cosine of the angle between the ray and the surface normal
};

// Renders the object (the caster's mesh, in the base frame) and, if given, the table plane, seen
// by a camera with these intrinsics (which must give the image size) at T_base_camera. Hits nearer
// than near_metres or farther than far_metres are left out.
RenderedView render_view(const geometry::MeshRayCaster& object, const Intrinsics& intrinsics,
                         const lie::Pose& base_from_camera,
                         const std::optional<geometry::Plane>& table, double near_metres = 0.1,
                         double far_metres = 10.0);

}  // namespace graspecmf::camera
