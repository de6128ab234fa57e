#pragma once
// Exact 3-D convex hull of a point set: quickhull driven by the exact orientation predicate, so
// the hull is always closed and convex, whatever the degeneracies of the input.

#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

// A convex hull mesh together with the volume it encloses.
struct ConvexHull {
  TriangleMesh mesh;    // as convex_hull returns it
  double volume = 0.0;  // 0 when the mesh is empty
};

// Convex hull of the points as a closed, outward triangle mesh whose vertices are some of the
// points (coplanar neighbours not merged); empty if the points span no volume.
TriangleMesh convex_hull(const std::vector<Vec3>& points);
// convex_hull(points) and its volume from one hull construction.
ConvexHull convex_hull_with_volume(const std::vector<Vec3>& points);

}  // namespace graspecmf::geometry
