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

// The little-endian float or double stored at data.
template <typename Float>
Float load(const char* data) {
  Float value;
  std::memcpy(&value, data, sizeof(Float));
  return value;
}

std::vector<Vec3> read_npy(const fs::path& path, const std::string& bytes) {
  const auto fail = [&](const std::string& why) { return Error(path.string() + ": " + why); };
  if (bytes.size() < 10 || bytes.compare(0, 6, "\x93NUMPY") != 0) throw fail("not a .npy file");
  const int major = static_cast<unsigned char>(bytes[6]);
  const std::size_t length_bytes = major == 1 ? 2 : 4;
  std::size_t header_length = 0;
  for (std::size_t i = 0; i < length_bytes; ++i) {
    header_length |= static_cast<std::size_t>(static_cast<unsigned char>(bytes[8 + i])) << (8 * i);
  }
  const std::size_t data_start = 8 + length_bytes + header_length;
  if (bytes.size() < data_start) throw fail("truncated .npy header");
  const std::string header = bytes.substr(8 + length_bytes, header_length);
  std::size_t width = 0;
  if (header.find("'<f4'") != std::string::npos) width = 4;
  if (header.find("'<f8'") != std::string::npos) width = 8;
  if (width == 0) throw fail(".npy data must be little-endian float32 or float64");
  if (header.find("'fortran_order': False") == std::string::npos) {
    throw fail(".npy data must be in C order");
  }
  const std::size_t shape_at = header.find("'shape': (");
  std::size_t rows = 0, cols = 0;
  if (shape_at == std::string::npos ||
      std::sscanf(header.c_str() + shape_at, "'shape': (%zu, %zu)", &rows, &cols) != 2 ||
      cols != 3) {
    throw fail(".npy array must have shape (N, 3)");
  }
  // Compared by division: rows * 3 * width may wrap for a shape no file could hold.
  const std::size_t data_bytes = bytes.size() - data_start;
  if (data_bytes % (3 * width) != 0 || data_bytes / (3 * width) != rows) {
    throw fail(".npy data size does not match its shape");
  }
  std::vector<Vec3> points(rows);
  const char* data = bytes.data() + data_start;
  for (std::size_t i = 0; i < 3 * rows; ++i) {
    points[i / 3][static_cast<Eigen::Index>(i % 3)] =
        width == 4 ? load<float>(data + 4 * i) : load<double>(data + 8 * i);
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
