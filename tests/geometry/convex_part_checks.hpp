#pragma once
// Checks shared by the convex hull, decomposition and cache tests: point containment in a convex
// part, a part's convexity and closedness, and equality of part lists.

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "graspecmf/geometry/exact_predicates.hpp"
#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"
#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry::testing {

// True if q lies on the inner side of (or on) every face plane of the convex part.
inline bool in_part(const TriangleMesh& part, const Vec3& q) {
  return std::all_of(part.triangles.begin(), part.triangles.end(), [&](const Triangle& t) {
    return orientation(part.vertices[t[0]], part.vertices[t[1]], part.vertices[t[2]], q) <= 0;
  });
}

// Closed, consistently outward, positive volume, and every vertex on or below every face plane.
inline void expect_convex_part(const TriangleMesh& part) {
  const MeshTopology topology = analyze_topology(part);
  EXPECT_TRUE(topology.watertight);
  EXPECT_TRUE(topology.consistently_oriented);
  EXPECT_EQ(topology.genus, 0);
  EXPECT_GT(mass_properties(part).volume, 0.0);
  for (const Vec3& v : part.vertices) EXPECT_TRUE(in_part(part, v));
}

// The same parts in the same order, bit for bit.
inline void expect_same_parts(const std::vector<TriangleMesh>& a,
                              const std::vector<TriangleMesh>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].vertices, b[i].vertices);
    EXPECT_EQ(a[i].triangles, b[i].triangles);
  }
}

}  // namespace graspecmf::geometry::testing
