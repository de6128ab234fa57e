#pragma once
// Combinatorial checks of a triangle mesh: edge manifoldness, watertightness, consistent
// orientation, connected components, Euler characteristic and genus.

#include <cstddef>
#include <string>
#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

struct MeshTopology {
  std::size_t num_vertices = 0;           // vertices used by at least one triangle
  std::size_t num_edges = 0;              // distinct undirected edges
  std::size_t num_boundary_edges = 0;     // edges with exactly one triangle
  std::size_t num_nonmanifold_edges = 0;  // edges with three or more triangles
  std::size_t num_misoriented_edges =
      0;                               // two-triangle edges traversed in the same direction twice
  std::size_t num_components = 0;      // edge-connected triangle components
  long euler_characteristic = 0;       // V − E + F
  bool watertight = false;             // every edge shared by exactly two triangles
  bool consistently_oriented = false;  // watertight and no misoriented edge
  int genus = -1;  // Σ over components of (2 − χ_c) / 2; −1 unless consistently oriented
};

// Analyses the mesh's edges (vertices are matched by index, so weld first); the mesh must be valid.
MeshTopology analyze_topology(const TriangleMesh& mesh);
// Throws Error (prefixed with `what`) unless the mesh is valid and watertight, naming the counts of
// boundary and non-manifold edges.
void require_watertight(const TriangleMesh& mesh, const std::string& what);
// Splits the mesh into its edge-connected components, each with its own compact vertex list, in
// order of their first triangle.
std::vector<TriangleMesh> connected_components(const TriangleMesh& mesh);

}  // namespace graspecmf::geometry
