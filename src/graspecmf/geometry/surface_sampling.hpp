#pragma once
// Area-weighted uniform sampling of points on a mesh surface, seeded and reproducible.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

struct SurfacePoints {
  std::vector<Vec3> points;
  std::vector<Vec3> normals;             // unit normal of the triangle each point lies on
  std::vector<std::uint32_t> triangles;  // index of that triangle
};

// Precomputes the area distribution once so that repeated draws (one per training step) are cheap.
class SurfaceSampler {
 public:
  // Keeps a reference: mesh must outlive the sampler. Throws Error if the mesh has zero total area.
  explicit SurfaceSampler(const TriangleMesh& mesh);
  // n points, uniform with respect to surface area (zero-area triangles are never chosen).
  SurfacePoints sample(std::size_t n, Rng& rng) const;

 private:
  const TriangleMesh& mesh_;
  std::vector<double> cumulative_area_;
};

// Convenience: n uniform surface points from a seed.
SurfacePoints sample_surface(const TriangleMesh& mesh, std::size_t n, std::uint64_t seed);

}  // namespace graspecmf::geometry
