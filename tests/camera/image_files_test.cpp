// Camera files: PNG images, depth images, masks, intrinsics and camera poses, each read back as
// written, and each kind of bad file refused with one clear error.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "graspecmf/camera/camera_pose.hpp"
#include "graspecmf/camera/depth_image.hpp"
#include "graspecmf/camera/intrinsics.hpp"
#include "graspecmf/camera/png_image.hpp"
#include "graspecmf/core/npy.hpp"
#include "graspecmf/lie/so3.hpp"
#include "test_support.hpp"

namespace graspecmf::camera {
namespace {

using graspecmf::testing::expect_error;
using graspecmf::testing::ScratchDir;
using graspecmf::testing::write_file;

GrayImage gradient(int bits) {
  GrayImage image;
  image.width = 7;
  image.height = 5;
  image.bits = bits;
  for (int i = 0; i < 35; ++i)
    image.values.push_back(static_cast<std::uint16_t>(i * (bits == 16 ? 1871 : 7)));
  return image;
}

TEST(PngImage, RoundTripsEightAndSixteenBits) {
  const ScratchDir dir;
  for (const int bits : {8, 16}) {
    write_png(gradient(bits), dir / "g.png");
    const GrayImage back = read_png(dir / "g.png");
    EXPECT_EQ(back.width, 7);
    EXPECT_EQ(back.height, 5);
    EXPECT_EQ(back.bits, bits);
    EXPECT_EQ(back.values, gradient(bits).values);
  }
}

TEST(PngImage, BadImagesGetOneClearError) {
  const ScratchDir dir;
  write_file(dir / "text.png", "not a png");
  expect_error([&] { read_png(dir / "text.png"); }, "not a readable PNG");
  expect_error([&] { read_png(dir / "missing.png"); }, "missing.png");
  GrayImage bad = gradient(8);
  bad.values[3] = 300;
  expect_error([&] { write_png(bad, dir / "bad.png"); }, "exceeds 255");
  bad.values.pop_back();
  expect_error([&] { write_png(bad, dir / "bad.png"); }, "does not match");
}

DepthImage ramp() {
  DepthImage depth;
  depth.width = 4;
  depth.height = 3;
  depth.metres = {0.0f, 0.5f, 0.5004f, 0.6f, 1.25f, 2.0f, 0.0f, 0.3f, 0.301f, 0.302f, 4.9f, 0.1f};
  return depth;
}

TEST(DepthImage, SixteenBitPngHoldsMillimetres) {
  const ScratchDir dir;
  write_depth_png(ramp(), dir / "d.png");
  const DepthImage back = read_depth_image(dir / "d.png");
  ASSERT_EQ(back.metres.size(), 12u);
  for (std::size_t i = 0; i < 12; ++i) EXPECT_NEAR(back.metres[i], ramp().metres[i], 0.0005 + 1e-6);
  EXPECT_EQ(back.metres[0], 0.0f);  // no reading stays no reading
  EXPECT_FLOAT_EQ(back.at(1, 1), 2.0f);
  // Another unit: tenths of a millimetre.
  write_depth_png(ramp(), dir / "d.png", 1e-4);
  EXPECT_NEAR(read_depth_image(dir / "d.png", 1e-4).at(2, 0), 0.5004f, 1e-6);
}

TEST(DepthImage, NpyInMetresOrIntegerMillimetres) {
  const ScratchDir dir;
  NpyArray metres{{3, 4}, {}};
  for (const float v : ramp().metres) metres.values.push_back(v);
  metres.values[6] = std::nan("");
  write_file(dir / "m.npy", npy_bytes(metres));
  const DepthImage back = read_depth_image(dir / "m.npy");
  EXPECT_EQ(back.width, 4);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.metres[6], 0.0f);  // NaN is no reading
  EXPECT_FLOAT_EQ(back.metres[5], 2.0f);
  // NumPy's uint16 millimetres, as a depth PNG read with NumPy is.
  std::string u16 = "\x93NUMPY\x01";
  std::string header = "{'descr': '<u2', 'fortran_order': False, 'shape': (1, 2), }";
  header.append(128 - 10 - header.size() - 1, ' ');
  header += '\n';
  u16 += '\0';
  u16 += static_cast<char>(header.size());
  u16 += '\0';
  u16 += header;
  u16 += std::string("\xe8\x03\x00\x00", 4);  // 1000, 0
  write_file(dir / "mm.npy", u16);
  const DepthImage mm = read_depth_image(dir / "mm.npy");
  EXPECT_FLOAT_EQ(mm.metres[0], 1.0f);
  EXPECT_EQ(mm.metres[1], 0.0f);
}

TEST(DepthImage, BadDepthGetsOneClearError) {
  const ScratchDir dir;
  write_png(gradient(8), dir / "eight.png");
  expect_error([&] { read_depth_image(dir / "eight.png"); }, "8-bit PNG cannot hold depth");
  write_file(dir / "row.npy", npy_bytes({{3}, {1, 2, 3}}));
  expect_error([&] { read_depth_image(dir / "row.npy"); }, "shape (height, width)");
  write_file(dir / "negative.npy", npy_bytes({{1, 2}, {1, -2}}));
  expect_error([&] { read_depth_image(dir / "negative.npy"); }, "negative");
  expect_error([&] { read_depth_image(dir / "d.exr"); }, "16-bit .png or a .npy");
  expect_error([&] { read_depth_image(dir / "eight.png", 0.0); }, "depth unit");
  DepthImage far = ramp();
  far.metres[3] = 70.0f;
  expect_error([&] { write_depth_png(far, dir / "far.png"); }, "16-bit PNG");
}

TEST(Mask, PngOrNpyOfTheDepthImagesSize) {
  const ScratchDir dir;
  const std::vector<std::uint8_t> mask = {0, 1, 1, 0, 0, 0, 1, 0, 0, 1, 1, 1};
  write_mask_png(mask, 4, 3, dir / "m.png");
  EXPECT_EQ(read_mask(dir / "m.png", 4, 3), mask);
  NpyArray array{{3, 4}, {}};
  for (const std::uint8_t v : mask) array.values.push_back(v * 3.0);
  write_file(dir / "m.npy", npy_bytes(array));
  EXPECT_EQ(read_mask(dir / "m.npy", 4, 3), mask);
  expect_error([&] { read_mask(dir / "m.png", 640, 480); },
               "the mask is 4 × 3 pixels but the depth image is 640 × 480");
}

TEST(Intrinsics, JsonAndRosYamlLayouts) {
  const ScratchDir dir;
  write_file(
      dir / "a.json",
      R"({"fx": 615.5, "fy": 614.0, "cx": 321.0, "cy": 239.5, "width": 640, "height": 480})");
  write_file(dir / "b.json", R"({"K": [[615.5, 0, 321.0], [0, 614.0, 239.5], [0, 0, 1]]})");
  write_file(
      dir / "c.yaml",
      "header:\n  frame_id: camera_color_optical_frame\nheight: 480\nwidth: 640\n"
      "distortion_model: plumb_bob\nK: [615.5, 0.0, 321.0, 0.0, 614.0, 239.5, 0.0, 0.0, 1.0]\n");
  write_file(dir / "d.yml",
             "height: 480\nwidth: 640\nk: [615.5, 0, 321.0, 0, 614.0, 239.5, 0, 0, 1]\n");
  write_file(dir / "e.yaml",
             "image_width: 640\nimage_height: 480\ncamera_name: head\ncamera_matrix:\n  rows: 3\n"
             "  cols: 3\n  data: [615.5, 0, 321.0, 0, 614.0, 239.5, 0, 0, 1]\n");
  for (const char* name : {"a.json", "b.json", "c.yaml", "d.yml", "e.yaml"}) {
    SCOPED_TRACE(name);
    const Intrinsics k = read_intrinsics(dir / name);
    EXPECT_EQ(k.fx, 615.5);
    EXPECT_EQ(k.fy, 614.0);
    EXPECT_EQ(k.cx, 321.0);
    EXPECT_EQ(k.cy, 239.5);
    EXPECT_EQ(k.width, std::string(name) == "b.json" ? 0 : 640);
    EXPECT_EQ(k.height, std::string(name) == "b.json" ? 0 : 480);
  }
}

TEST(Intrinsics, BadFilesGetOneClearError) {
  const ScratchDir dir;
  write_file(dir / "a.json", R"({"fx": 615.5, "cx": 321.0, "cy": 239.5})");
  expect_error([&] { read_intrinsics(dir / "a.json"); }, "no \"fy\"");
  write_file(dir / "b.json", R"({"K": [1, 0, 2, 0, 1, 2]})");
  expect_error([&] { read_intrinsics(dir / "b.json"); }, "has 6 numbers, not 9");
  write_file(dir / "c.json", R"({"fx": -1, "fy": 1, "cx": 0, "cy": 0})");
  expect_error([&] { read_intrinsics(dir / "c.json"); }, "must be positive");
  write_file(dir / "d.json", R"({"fx": "a", "fy": 1, "cx": 0, "cy": 0})");
  expect_error([&] { read_intrinsics(dir / "d.json"); }, "must be numbers");
  write_file(dir / "e.yaml", "K: [1, 0, 2, 0, 1, 2, 0, 0, 5]\n");
  expect_error([&] { read_intrinsics(dir / "e.yaml"); }, "not of the form");
  write_file(dir / "f.yaml", "width: 640\n");
  expect_error([&] { read_intrinsics(dir / "f.yaml"); }, "no camera matrix");
  write_file(dir / "g.yaml", "K: [1, 0, 2\n");
  expect_error([&] { read_intrinsics(dir / "g.yaml"); }, "g.yaml");
  expect_error([&] { read_intrinsics(dir / "k.txt"); }, ".json or .yaml");
}

TEST(CameraPose, RoundTripAndLookAt) {
  const ScratchDir dir;
  const lie::Pose pose = look_at({0.5, -0.3, 0.6}, {0.0, 0.0, 0.05}, {0, 0, 1});
  // The optical frame: z towards the target, y (image down) with a negative world-z component.
  EXPECT_NEAR((pose.R.col(2) - (lie::Vec3(0.0, 0.0, 0.05) - pose.p).normalized()).norm(), 0, 1e-12);
  EXPECT_LT(pose.R.col(1).z(), 0.0);
  EXPECT_NEAR((pose.R.transpose() * pose.R - lie::Mat3::Identity()).norm(), 0, 1e-12);
  EXPECT_NEAR(pose.R.determinant(), 1.0, 1e-12);
  write_camera_pose(pose, dir / "T.json");
  const lie::Pose back = read_camera_pose(dir / "T.json");
  EXPECT_LT((back.matrix() - pose.matrix()).cwiseAbs().maxCoeff(), 1e-12);
  write_file(dir / "bare.json", "[[1,0,0,0.1],[0,1,0,0],[0,0,1,0],[0,0,0,1]]");
  EXPECT_EQ(read_camera_pose(dir / "bare.json").p.x(), 0.1);
  write_file(dir / "row.json", "[[1,0,0,0.1],[0,1,0,0],[0,0,1,0],[0,0,1,1]]");
  expect_error([&] { read_camera_pose(dir / "row.json"); }, "last row");
  write_file(dir / "scaled.json", "[[2,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]");
  expect_error([&] { read_camera_pose(dir / "scaled.json"); }, "not a rotation");
  write_file(dir / "short.json", "{\"matrix\": [[1,0,0],[0,1,0],[0,0,1]]}");
  expect_error([&] { read_camera_pose(dir / "short.json"); }, "4 × 4 matrix");
  expect_error([] { look_at({0, 0, 1}, {0, 0, 0}, {0, 0, 1}); }, "parallel");
}

}  // namespace
}  // namespace graspecmf::camera
