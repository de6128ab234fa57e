#pragma once
// Approximate convex decomposition of a closed triangle mesh, for simulators that collide a mesh as
// its convex hull (MuJoCo would otherwise fill a mug's cavity and its handle hole).

#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

struct DecompositionOptions {
  int resolution = 64;       // lattice cells along the longest side (cut positions), [4, 256]
  int max_parts = 64;        // the decomposition has at most this many parts, ≥ 1
  double concavity = 0.002;  // tolerated hull − solid volume of a part, × the mesh volume; ≥ 0
  int planes_per_axis = 4;   // evenly spaced cut planes tried per axis before refining, ≥ 1
};

// Convex parts (closed, outward) whose union contains the closed mesh's solid; deterministic.
// Throws Error if the mesh is invalid or not watertight, or an option is outside its range.
std::vector<TriangleMesh> convex_decomposition(const TriangleMesh& mesh,
                                               const DecompositionOptions& options = {});

}  // namespace graspecmf::geometry
