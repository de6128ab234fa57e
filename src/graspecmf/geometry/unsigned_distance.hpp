#pragma once
// Unsigned distance from points to a triangle mesh's surface (an AABB tree over its triangles).
// Open and non-manifold meshes are fine: the distance is to the nearest triangle, inside or out.

#include <memory>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

class UnsignedDistance {
 public:
  // Builds the tree over the mesh's triangles whose corners are not collinear (exact predicate).
  // Throws Error if the mesh is invalid or every triangle has zero area.
  explicit UnsignedDistance(const TriangleMesh& mesh);
  ~UnsignedDistance();
  UnsignedDistance(UnsignedDistance&&) noexcept;
  UnsignedDistance& operator=(UnsignedDistance&&) noexcept;

  // The distance from q to the nearest point of the surface, in the mesh's units.
  double operator()(const Vec3& q) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace graspecmf::geometry
