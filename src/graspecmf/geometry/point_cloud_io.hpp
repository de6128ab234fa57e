#pragma once
// Point clouds from files: .xyz/.txt (whitespace-separated rows, x y z first), .npy (float32 or
// float64, shape (N, 3), C order, little endian) and .ply (ascii or binary of either byte order;
// the scalar x, y, z of the vertex element, of any PLY type; everything else is skipped).

#include <filesystem>
#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

// Reads the points by extension (case-insensitive). Throws Error naming the file if it is missing,
// malformed or truncated, holds no point, or holds a non-finite coordinate.
std::vector<Vec3> read_point_cloud(const std::filesystem::path& path);

}  // namespace graspecmf::geometry
