#include "graspecmf/geometry/point_cloud_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/input_file.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "test_support.hpp"

namespace graspecmf::geometry {
namespace {

using graspecmf::testing::ScratchDir;
using graspecmf::testing::write_file;

const std::vector<Vec3> kPoints = {{0.1, -2.5, 3.0}, {1e-3, 0.0, -7.25}, {4.0, 5.5, 6.125}};

template <typename T>
std::string raw(T value) {
  std::string bytes(sizeof(T), '\0');
  std::memcpy(bytes.data(), &value, sizeof(T));
  return bytes;
}

// A version-1 .npy file with the given dtype and shape around the data bytes.
std::string npy(const std::string& dtype, const std::string& shape, const std::string& data) {
  std::string header =
      "{'descr': '" + dtype + "', 'fortran_order': False, 'shape': " + shape + ", }";
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  return std::string("\x93NUMPY\x01\x00", 8) + raw(static_cast<std::uint16_t>(header.size())) +
         header + data;
}

template <typename T>
std::string npy_of(const std::vector<Vec3>& points, const std::string& dtype) {
  std::string data;
  for (const Vec3& p : points) {
    for (int k = 0; k < 3; ++k) data += raw(static_cast<T>(p[k]));
  }
  return npy(dtype, "(" + std::to_string(points.size()) + ", 3)", data);
}

void expect_points(const std::vector<Vec3>& got, double tolerance) {
  ASSERT_EQ(got.size(), kPoints.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_LE((got[i] - kPoints[i]).norm(), tolerance) << i;
  }
}

TEST(PointCloudIo, ReadsXyzWithCommentsAndExtraColumns) {
  const ScratchDir dir;
  write_file(dir / "c.xyz", "# x y z nx ny nz\n0.1 -2.5 3 0 0 1\n\n1e-3 0 -7.25\n4 5.5 6.125 9\n");
  expect_points(read_point_cloud(dir / "c.xyz"), 0.0);
}

TEST(PointCloudIo, ReadsNpyFloat32AndFloat64) {
  const ScratchDir dir;
  write_file(dir / "d.npy", npy_of<double>(kPoints, "<f8"));
  expect_points(read_point_cloud(dir / "d.npy"), 0.0);
  write_file(dir / "f.NPY", npy_of<float>(kPoints, "<f4"));
  expect_points(read_point_cloud(dir / "f.NPY"), 1e-6);
}

TEST(PointCloudIo, ReadsAsciiAndBinaryPlyWithOtherProperties) {
  const ScratchDir dir;
  write_file(dir / "a.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float nx\nproperty double x\n"
             "property double y\nproperty double z\nproperty uchar red\nelement face 0\n"
             "property list uchar int vertex_indices\nend_header\n"
             "9 0.1 -2.5 3 255\n9 1e-3 0 -7.25 0\n9 4 5.5 6.125 1\n");
  expect_points(read_point_cloud(dir / "a.ply"), 0.0);
  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty uchar red\n"
      "property float x\nproperty float y\nproperty float z\nend_header\n";
  for (const Vec3& p : kPoints) {
    binary += raw(static_cast<std::uint8_t>(7));
    for (int k = 0; k < 3; ++k) binary += raw(static_cast<float>(p[k]));
  }
  write_file(dir / "b.ply", binary);
  expect_points(read_point_cloud(dir / "b.ply"), 1e-6);
  write_file(dir / "cut.ply", binary.substr(0, binary.size() - 2));
  EXPECT_THROW(read_point_cloud(dir / "cut.ply"), Error);
}

// A tiny binary PLY whose header declares a billion vertices and faces: refused before any
// allocation, as a cloud and as a mesh.
TEST(PointCloudIo, PlyDeclaringMoreThanItHoldsIsRefused) {
  const ScratchDir dir;
  write_file(dir / "huge.ply",
             "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\n"
             "property float x\nproperty float y\nproperty float z\nelement face 1000000000\n"
             "property list uchar int vertex_indices\nend_header\n" +
                 std::string(36, '\0'));
  graspecmf::testing::expect_error([&] { read_point_cloud(dir / "huge.ply"); },
                                   "declares more data than the file holds (36 bytes");
  graspecmf::testing::expect_error([&] { read_mesh(dir / "huge.ply"); },
                                   "declares more data than the file holds");
}

TEST(PointCloudIo, BadFilesAreOneClearError) {
  const ScratchDir dir;
  EXPECT_THROW(read_point_cloud(dir / "missing.xyz"), Error);
  write_file(dir / "c.pcd", "x");
  EXPECT_THROW(read_point_cloud(dir / "c.pcd"), Error);
  write_file(dir / "empty.xyz", "# nothing\n");
  EXPECT_THROW(read_point_cloud(dir / "empty.xyz"), Error);
  write_file(dir / "short.xyz", "1 2\n");
  EXPECT_THROW(read_point_cloud(dir / "short.xyz"), Error);
  std::vector<Vec3> nan = kPoints;
  nan[1].y() = std::nan("");
  write_file(dir / "nan.npy", npy_of<double>(nan, "<f8"));
  EXPECT_THROW(read_point_cloud(dir / "nan.npy"), Error);
  write_file(dir / "shape.npy", npy("<f8", "(3, 2)", std::string(48, '\0')));
  EXPECT_THROW(read_point_cloud(dir / "shape.npy"), Error);
  const std::string whole = npy_of<double>(kPoints, "<f8");
  write_file(dir / "cut.npy", whole.substr(0, whole.size() - 1));
  EXPECT_THROW(read_point_cloud(dir / "cut.npy"), Error);
  write_file(dir / "big_endian.npy", npy(">f4", "(1, 3)", std::string(12, '\0')));
  EXPECT_THROW(read_point_cloud(dir / "big_endian.npy"), Error);
  write_file(dir / "huge.xyz", "");  // sparse, over the input cap: refused by its size
  std::filesystem::resize_file(dir / "huge.xyz", kMaxInputFileBytes + 1);
  EXPECT_THROW(read_point_cloud(dir / "huge.xyz"), Error);
}

}  // namespace
}  // namespace graspecmf::geometry

// Found by hand while fuzzing read_npy: a shape whose byte count wraps around 2^64 passed the size
// check and threw std::length_error.
TEST(FuzzRegressions, NpyShapeWhoseSizeOverflows) {
  graspecmf::testing::expect_error(
      [] {
        graspecmf::geometry::read_point_cloud(
            graspecmf::testing::fuzz_regression("npy", "shape_rows_overflow.npy"));
      },
      "data size does not match its shape");
}
