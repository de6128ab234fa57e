#pragma once
// Solid voxelisation of a closed triangle mesh. Vertical lines of a regular (x, y) lattice are cast
// along +z against the triangles they pass through (found by rasterising each triangle's
// projection), and the signed crossings are summed upwards (non-zero winding rule, so either
// orientation works): each line gets the exact z intervals where it is inside the solid. A voxel is
// occupied when its centre is inside. A line that passes exactly through an edge or vertex is moved
// by a symbolic perturbation (−ε, −ε²) in (x, y), with each edge's test evaluated once, so the
// triangles sharing it agree and no crossing is lost or counted twice.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

// Where the vertical lines (x0 + i·spacing, y0 + j·spacing), 0 ≤ i < nx, 0 ≤ j < ny, are inside.
struct ColumnSpans {
  double x0 = 0.0;
  double y0 = 0.0;
  double spacing = 0.0;
  int nx = 0;
  int ny = 0;
  std::vector<std::uint32_t> first;  // line l = i + nx·j owns spans[first[l], first[l + 1])
  std::vector<std::array<double, 2>> spans;  // [enter, leave) in z, increasing and disjoint

  // True if height z of line (i, j) is inside the solid (an entering height is, a leaving one not).
  bool inside(int i, int j, double z) const;
  // Length of line (i, j) inside the solid between heights lo and hi.
  double inside_length(int i, int j, double lo, double hi) const;
};

struct VoxelGrid {
  Vec3 origin = Vec3::Zero();           // minimum corner of voxel (0, 0, 0)
  double voxel_size = 0.0;              // edge length of the cubic voxels
  std::array<int, 3> dims = {0, 0, 0};  // voxels along x, y and z
  std::vector<std::uint8_t> occupied;   // 1 where the centre is inside; x fastest, then y, then z

  // Position of voxel (i, j, k) in `occupied`.
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(dims[0]) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims[1]) * k);
  }
  bool at(int i, int j, int k) const { return occupied[index(i, j, k)] != 0; }
  // Centre of voxel (i, j, k).
  Vec3 center(int i, int j, int k) const {
    return origin + voxel_size * Vec3(i + 0.5, j + 0.5, k + 0.5);
  }
  // Number of occupied voxels.
  std::size_t count() const;
  // count() × voxel_size³.
  double volume() const;
};

// The inside spans of an nx × ny lattice of vertical lines starting at (x0, y0). Throws Error if
// the mesh is invalid or not watertight, spacing is not positive and finite, x0 or y0 is not
// finite, nx or ny is below 1, or the lattice has more than 2^26 lines.
ColumnSpans column_spans(const TriangleMesh& mesh, double x0, double y0, double spacing, int nx,
                         int ny);
// An unoccupied grid with `resolution` cubic voxels along the longest side of the box, centred on
// it and covering it (the other sides get as many voxels as they need). Throws Error if resolution
// is outside [1, 1024] or the box has no extent.
VoxelGrid fitted_grid(const BoundingBox& box, int resolution);
// Voxelises the closed mesh on fitted_grid(bounding_box(mesh), resolution). Throws Error as
// fitted_grid and column_spans do.
VoxelGrid voxelize(const TriangleMesh& mesh, int resolution);
// Voxelises the closed mesh on the given grid; parts of the mesh outside it are not sampled.
// Throws Error as column_spans does (voxel_size is the spacing), if origin is not finite, or if
// the grid has no voxel or more than 2^30.
VoxelGrid voxelize(const TriangleMesh& mesh, const Vec3& origin, double voxel_size,
                   const std::array<int, 3>& dims);

}  // namespace graspecmf::geometry
