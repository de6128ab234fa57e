#include "graspecmf/geometry/surface_sampling.hpp"

#include <algorithm>
#include <cmath>

#include "graspecmf/core/error.hpp"

namespace graspecmf::geometry {

SurfaceSampler::SurfaceSampler(const TriangleMesh& mesh) : mesh_(mesh) {
  cumulative_area_.reserve(mesh.triangles.size());
  double total = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    total += triangle_area(mesh, t);
    cumulative_area_.push_back(total);
  }
  if (!(total > 0.0) || !std::isfinite(total)) {
    throw Error("cannot sample the surface: the mesh has zero (or non-finite) total area");
  }
}

SurfacePoints SurfaceSampler::sample(std::size_t n, Rng& rng) const {
  SurfacePoints out;
  out.points.reserve(n);
  out.normals.reserve(n);
  out.triangles.reserve(n);
  const double total = cumulative_area_.back();
  const std::size_t last = cumulative_area_.size() - 1;
  for (std::size_t i = 0; i < n; ++i) {
    // First triangle whose cumulative area exceeds u; zero-area triangles are never chosen.
    const double u = rng.uniform() * total;
    const auto it = std::upper_bound(cumulative_area_.begin(), cumulative_area_.end(), u);
    const std::size_t t = std::min(static_cast<std::size_t>(it - cumulative_area_.begin()), last);
    const Triangle& tri = mesh_.triangles[t];
    // Uniform in the triangle: barycentrics (1 − √r1, √r1 (1 − r2), √r1 r2).
    const double s = std::sqrt(rng.uniform());
    const double r2 = rng.uniform();
    out.points.push_back((1.0 - s) * mesh_.vertices[tri[0]] +
                         s * (1.0 - r2) * mesh_.vertices[tri[1]] + s * r2 * mesh_.vertices[tri[2]]);
    out.normals.push_back(triangle_normal(mesh_, t));
    out.triangles.push_back(static_cast<std::uint32_t>(t));
  }
  return out;
}

SurfacePoints sample_surface(const TriangleMesh& mesh, std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  return SurfaceSampler(mesh).sample(n, rng);
}

}  // namespace graspecmf::geometry
