#pragma once
// Ray casts and box overlap queries against a triangle mesh, accelerated by an axis-aligned
// bounding-volume hierarchy that is built once per mesh.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "graspecmf/geometry/oriented_box.hpp"
#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

struct RayHit {
  double t = 0.0;             // the hit is origin + t · direction (t in multiples of |direction|)
  Vec3 point = Vec3::Zero();  // origin + t · direction
  std::size_t triangle = 0;   // index into the mesh's triangles
};

class MeshRayCaster {
 public:
  // Copies the mesh (the caster never refers to the argument again) and builds the hierarchy:
  // median splits on the longest axis of the triangle centroids, at most 4 triangles per leaf,
  // deterministic. Throws Error if the mesh is invalid (validate_mesh), e.g. has no triangles.
  explicit MeshRayCaster(const TriangleMesh& mesh);

  // The caster's copy of the mesh.
  const TriangleMesh& mesh() const { return mesh_; }

  // The nearest crossing of the ray origin + t · direction, t ∈ [t_min, t_max], with a triangle
  // (Möller–Trumbore in double precision, either side, edges included; a tie goes to the lowest
  // triangle index). direction need not be unit; throws Error if it is zero or not finite, or if
  // origin is not finite.
  std::optional<RayHit> first_hit(const Vec3& origin, const Vec3& direction, double t_min = 0.0,
                                  double t_max = std::numeric_limits<double>::infinity()) const;

  // True if q lies inside the closed, consistently oriented mesh (is_inside's answer): the exact
  // signed count of the triangles a segment from q out of the bounding box crosses (orientation
  // predicates), trying other segments when one meets an edge, a vertex or a triangle's plane,
  // and the winding number if all of them do. On the surface itself the answer is not defined.
  bool contains(const Vec3& q) const;

  // True if the solid box meets a triangle (touching counts) or lies inside the mesh: the answer
  // of box_overlaps_mesh(box, mesh()) for a closed, consistently oriented mesh.
  bool overlaps(const OrientedBox& box) const;

 private:
  struct Node {
    Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // padded bounds of the node's triangles
    std::uint32_t first = 0;  // leaf: first slot in order_; inner node: index of the right child
    std::uint32_t count = 0;  // leaf: number of triangles (> 0); inner node: 0, left child follows
  };

  // Adds the node for order_[begin, end) and its subtree; returns the node's index.
  std::uint32_t build(std::uint32_t begin, std::uint32_t end, const std::vector<Vec3>& centroids);
  // Σ over the triangles the segment q → far crosses of +1 (leaving) or −1 (entering): the
  // winding number of q when far lies outside the mesh; nothing if the segment meets a triangle's
  // edge, vertex or plane other than by a proper crossing.
  std::optional<int> crossing_number(const Vec3& q, const Vec3& far) const;

  TriangleMesh mesh_;
  BoundingBox bounds_;  // unpadded bounds of the mesh
  // Margin added to every culling bound, so that rounding never culls a touching triangle.
  double pad_ = 0.0;
  std::vector<Node> nodes_;             // nodes_[0] is the root
  std::vector<std::uint32_t> order_;    // triangle indices; each leaf is a contiguous range
  std::vector<Vec3> corner_, e1_, e2_;  // per slot of order_: vertex 0 and the edges from it
};

}  // namespace graspecmf::geometry
