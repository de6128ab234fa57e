#include "graspecmf/camera/depth_render.hpp"

#include <cmath>

#include "graspecmf/core/error.hpp"

namespace graspecmf::camera {

RenderedView render_view(const geometry::MeshRayCaster& object, const Intrinsics& intrinsics,
                         const lie::Pose& base_from_camera,
                         const std::optional<geometry::Plane>& table, double near_metres,
                         double far_metres) {
  validate(intrinsics, "render_view");
  if (intrinsics.width == 0) throw Error("render_view: the intrinsics must give the image size");
  if (!(near_metres > 0.0) || !(far_metres > near_metres)) {
    throw Error("render_view: need 0 < near < far");
  }
  const geometry::TriangleMesh& mesh = object.mesh();
  RenderedView view;
  view.depth.width = intrinsics.width;
  view.depth.height = intrinsics.height;
  const std::size_t pixels = static_cast<std::size_t>(intrinsics.width) * intrinsics.height;
  view.depth.metres.assign(pixels, 0.0f);
  view.object_mask.assign(pixels, 0);
  view.incidence.assign(pixels, 0.0f);
  const lie::Mat3& R = base_from_camera.R;
  const lie::Vec3& eye = base_from_camera.p;
  for (int v = 0; v < intrinsics.height; ++v) {
    for (int u = 0; u < intrinsics.width; ++u) {
      // With the ray's camera-frame z component 1, the ray parameter t is the depth itself.
      const lie::Vec3 direction = R * back_project(intrinsics, u, v, 1.0);
      double depth = far_metres;
      lie::Vec3 normal = lie::Vec3::Zero();
      bool on_object = false;
      if (const auto hit = object.first_hit(eye, direction, near_metres, far_metres)) {
        const auto& t = mesh.triangles[hit->triangle];
        const lie::Vec3 n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                                .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        depth = hit->t;
        normal = n.normalized();
        on_object = true;
      }
      if (table) {
        const double rate = table->normal.dot(direction);
        if (rate != 0.0) {
          const double t = -table->signed_distance(eye) / rate;
          if (t >= near_metres && t < depth) {
            depth = t;
            normal = table->normal;
            on_object = false;
          }
        }
      }
      if (depth >= far_metres || !normal.allFinite() || normal.isZero()) continue;
      const std::size_t i = static_cast<std::size_t>(v) * intrinsics.width + u;
      view.depth.metres[i] = static_cast<float>(depth);
      view.object_mask[i] = on_object ? 1 : 0;
      view.incidence[i] = static_cast<float>(std::abs(normal.dot(direction.normalized())));
    }
  }
  return view;
}

}  // namespace graspecmf::camera
