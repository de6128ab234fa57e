#pragma once
// The bundled mug in metres and its default convex decomposition, each computed once per test
// binary (the decomposition takes ~0.3 s).

#include <vector>

#include "graspecmf/geometry/convex_decomposition.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "test_meshes.hpp"

namespace graspecmf::geometry::testing {

inline const TriangleMesh& metric_mug() {
  static const TriangleMesh mug = scaled(read_mesh(kMugPath), kMugScale);
  return mug;
}

inline const std::vector<TriangleMesh>& mug_parts() {
  static const std::vector<TriangleMesh> parts = convex_decomposition(metric_mug());
  return parts;
}

}  // namespace graspecmf::geometry::testing
