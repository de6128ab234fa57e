#pragma once
// Mesh files: OBJ (tinyobjloader), STL binary/ASCII and PLY (assimp) in; OBJ and PLY out.
// Read meshes are welded (vertices at identical positions merged) and validated.

#include <filesystem>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

// Reads .obj, .stl or .ply (case-insensitive extension); polygons are triangulated and vertices at
// identical positions merged. Throws Error (one line naming the file) if the file is missing,
// unreadable, truncated, or fails validate_mesh.
TriangleMesh read_mesh(const std::filesystem::path& path);
// Writes .obj (text) or .ply (binary little-endian) by extension, atomically, with full double
// precision so that read_mesh(write_mesh(m)) == m. Throws Error on another extension.
void write_mesh(const TriangleMesh& mesh, const std::filesystem::path& path);

}  // namespace graspecmf::geometry
