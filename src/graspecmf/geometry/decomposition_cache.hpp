#pragma once
// Disk cache for convex_decomposition: one checksummed binary file per mesh and option set, named
// by a hash of both, so that a decomposition is computed once per mesh.

#include <filesystem>
#include <vector>

#include "graspecmf/geometry/convex_decomposition.hpp"
#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

// The file in cache_dir that holds the decomposition of this mesh with these options: named by a
// 64-bit FNV-1a hash of the vertex and triangle bytes, the options and the format version.
std::filesystem::path decomposition_cache_file(const TriangleMesh& mesh,
                                               const DecompositionOptions& options,
                                               const std::filesystem::path& cache_dir);
// convex_decomposition read from decomposition_cache_file, or (missing or corrupt) computed and
// written there atomically, creating cache_dir. Throws Error as that does or if writing fails.
std::vector<TriangleMesh> cached_convex_decomposition(const TriangleMesh& mesh,
                                                      const DecompositionOptions& options,
                                                      const std::filesystem::path& cache_dir);

}  // namespace graspecmf::geometry
