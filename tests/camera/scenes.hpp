#pragma once
// Scenes the camera tests render: a UV sphere, a camera like a RealSense D435 at 640 × 480, and
// the sample mug standing on a table at z = 0.

#include <cmath>

#include "graspecmf/camera/camera_pose.hpp"
#include "graspecmf/camera/intrinsics.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/geometry/triangle_mesh.hpp"
#include "test_support.hpp"

namespace graspecmf::camera::testing {

// A sphere of radius r about centre, nu segments around and nv from pole to pole, outward faces.
inline geometry::TriangleMesh uv_sphere(const lie::Vec3& centre, double r, int nu, int nv) {
  geometry::TriangleMesh mesh;
  mesh.vertices.push_back(centre + lie::Vec3(0, 0, r));
  for (int j = 1; j < nv; ++j) {
    const double theta = M_PI * j / nv;
    for (int i = 0; i < nu; ++i) {
      const double phi = 2 * M_PI * i / nu;
      mesh.vertices.push_back(centre + r * lie::Vec3(std::sin(theta) * std::cos(phi),
                                                     std::sin(theta) * std::sin(phi),
                                                     std::cos(theta)));
    }
  }
  mesh.vertices.push_back(centre + lie::Vec3(0, 0, -r));
  const auto ring = [&](int j, int i) {
    return static_cast<unsigned>(1 + (j - 1) * nu + (i % nu));
  };
  const auto south = static_cast<unsigned>(mesh.vertices.size() - 1);
  for (int i = 0; i < nu; ++i) {
    mesh.triangles.push_back({0, ring(1, i), ring(1, i + 1)});
    for (int j = 1; j + 1 < nv; ++j) {
      mesh.triangles.push_back({ring(j, i), ring(j + 1, i), ring(j + 1, i + 1)});
      mesh.triangles.push_back({ring(j, i), ring(j + 1, i + 1), ring(j, i + 1)});
    }
    mesh.triangles.push_back({ring(nv - 1, i), south, ring(nv - 1, i + 1)});
  }
  return mesh;
}

// The sample mug in metres, standing on z = 0 with its bounding box centred on the z axis.
inline geometry::TriangleMesh mug_on_table() {
  geometry::TriangleMesh mug =
      geometry::scaled(geometry::read_mesh(graspecmf::testing::sample_mesh_file()), 0.0002682458);
  const geometry::BoundingBox box = geometry::bounding_box(mug);
  const lie::Vec3 shift(-0.5 * (box.min.x() + box.max.x()), -0.5 * (box.min.y() + box.max.y()),
                        -box.min.z());
  for (lie::Vec3& v : mug.vertices) v += shift;
  return mug;
}

}  // namespace graspecmf::camera::testing
