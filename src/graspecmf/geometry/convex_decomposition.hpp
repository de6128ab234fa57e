#pragma once
// Approximate convex decomposition of a closed triangle mesh, for simulators that collide a mesh as
// its convex hull (MuJoCo would otherwise fill a mug's cavity and its handle hole), with a disk
// cache, and the exact convex hull it is built on.
//
// The decomposition works on boxes (cells) of a regular lattice around the mesh. For each cell it
// knows the convex hull of the solid inside it exactly (built from the mesh surface clipped to the
// cell plus the cell corners inside the solid) and the solid's volume exactly (a flux integral).
// Phase 1 splits the cell whose hull exceeds its solid by the most, at the lattice plane that
// reduces that excess the most (or, when no plane helps much, across its longest side), until every
// excess is within the tolerance. Phase 2 merges touching cells, cheapest added hull volume first,
// down to the part budget. Every part is the hull of the solid in its cells, so the parts cover the
// solid exactly; hulls of merged cells may overlap a little.

#include <filesystem>
#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

struct DecompositionOptions {
  int resolution = 64;       // lattice cells along the longest side (cut positions), [4, 256]
  int max_parts = 64;        // the decomposition has at most this many parts
  double concavity = 0.002;  // tolerated hull − solid volume of a part, × the mesh volume
  int planes_per_axis = 4;   // evenly spaced cut planes tried per axis before refining
};

// Exact sign of ((b − a) × (c − a)) · (d − a): +1 if d lies above the plane of the
// counter-clockwise triangle abc, −1 below, 0 on it (adaptive: floating point with an error bound,
// exact expansion arithmetic when that cannot decide).
int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Convex hull of the points (quickhull with exact orientation tests) as a closed, outward mesh of
// triangles whose vertices are some of the points; coplanar neighbours are not merged. Empty if
// the points span no volume.
TriangleMesh convex_hull(const std::vector<Vec3>& points);

// Convex parts (closed, outward) whose union contains the closed mesh's solid; deterministic.
// Throws Error if the mesh is invalid or not watertight, resolution is outside [4, 256],
// max_parts or planes_per_axis is below 1, or concavity is negative or not finite.
std::vector<TriangleMesh> convex_decomposition(const TriangleMesh& mesh,
                                               const DecompositionOptions& options = {});

// The file in cache_dir that holds the decomposition of this mesh with these options: named by a
// 64-bit FNV-1a hash of the vertex and triangle bytes, the options and the format version.
std::filesystem::path decomposition_cache_file(const TriangleMesh& mesh,
                                               const DecompositionOptions& options,
                                               const std::filesystem::path& cache_dir);
// convex_decomposition, read from decomposition_cache_file when it holds a valid decomposition;
// otherwise (missing, truncated, corrupt) computed and written there atomically, creating
// cache_dir if needed. Throws Error as convex_decomposition does, or if the file cannot be written.
std::vector<TriangleMesh> cached_convex_decomposition(const TriangleMesh& mesh,
                                                      const DecompositionOptions& options,
                                                      const std::filesystem::path& cache_dir);

}  // namespace graspecmf::geometry
