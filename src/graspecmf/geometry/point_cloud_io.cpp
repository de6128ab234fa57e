#include "graspecmf/geometry/point_cloud_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/input_file.hpp"
#include "graspecmf/core/npy.hpp"
#include "graspecmf/geometry/ply_body.hpp"
#include "graspecmf/geometry/ply_header.hpp"

namespace graspecmf::geometry {
namespace fs = std::filesystem;
namespace {

std::vector<Vec3> read_xyz(const fs::path& path, const std::string& bytes) {
  std::vector<Vec3> points;
  std::istringstream lines(bytes);
  std::string line;
  std::size_t number = 0;
  while (std::getline(lines, line)) {
    ++number;
    const std::size_t start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos || line[start] == '#') continue;
    std::istringstream row(line);
    Vec3 p;
    if (!(row >> p.x() >> p.y() >> p.z())) {
      throw Error(path.string() + ": line " + std::to_string(number) + " is not x y z");
    }
    points.push_back(p);
  }
  return points;
}

std::vector<Vec3> read_npy(const fs::path& path, const std::string& bytes) {
  const NpyArray array = parse_npy(bytes, path.string());
  if (array.shape.size() != 2 || array.shape[1] != 3) {
    throw Error(path.string() + ": .npy array must have shape (N, 3)");
  }
  std::vector<Vec3> points(array.shape[0]);
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i] = Vec3(array.values[3 * i], array.values[3 * i + 1], array.values[3 * i + 2]);
  }
  return points;
}

std::vector<Vec3> read_ply(const fs::path& path, const std::string& bytes) {
  const PlyHeader header = read_ply_header(path, bytes, bytes.size());
  return ply_points(read_ply_columns(path, bytes, header, ply_xyz_names(path, header)));
}

}  // namespace

std::vector<Vec3> read_point_cloud(const fs::path& path) {
  const std::string ext = lower_extension(path);
  if (ext != ".xyz" && ext != ".txt" && ext != ".npy" && ext != ".ply") {
    throw Error(path.string() + ": point clouds must be .xyz, .txt, .npy or .ply");
  }
  const std::string bytes = read_input_file(path);
  const std::vector<Vec3> points = ext == ".npy"   ? read_npy(path, bytes)
                                   : ext == ".ply" ? read_ply(path, bytes)
                                                   : read_xyz(path, bytes);
  if (points.empty()) throw Error(path.string() + ": the point cloud is empty");
  for (const Vec3& p : points) {
    if (!p.allFinite())
      throw Error(path.string() + ": the point cloud has a non-finite coordinate");
  }
  return points;
}

}  // namespace graspecmf::geometry
