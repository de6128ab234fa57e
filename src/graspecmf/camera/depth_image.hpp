#pragma once
// Depth images and object masks as cameras and datasets store them: depth as a 16-bit PNG of
// integer units (millimetres by default) or a float .npy in metres; a mask as a PNG or .npy whose
// non-zero pixels are the object.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace graspecmf::camera {

// Depth along the viewing axis, row-major from the top-left pixel.
struct DepthImage {
  int width = 0;
  int height = 0;
  std::vector<float> metres;  // width × height; 0 where the camera has no reading

  float at(int u, int v) const { return metres[static_cast<std::size_t>(v) * width + u]; }
};

// The PNG unit of depth most cameras and datasets write: millimetres.
inline constexpr double kDefaultPngMetresPerUnit = 0.001;

// Reads a depth image: a 16-bit PNG (value × png_metres_per_unit; 0 is no reading) or a float .npy
// of shape (H, W) in metres (NaN, ±inf and 0 are no reading). Throws Error "<path>: <why>" for an
// 8-bit PNG, another shape, a negative depth, or png_metres_per_unit not positive and finite.
DepthImage read_depth_image(const std::filesystem::path& path,
                            double png_metres_per_unit = kDefaultPngMetresPerUnit);

// A depth image from row-major values of shape (height, width), each times `scale` metres (NaN and
// ±inf are no reading). Throws Error "<what>: <why>" for a negative value or an empty shape.
DepthImage depth_from_values(const std::vector<double>& values, int height, int width, double scale,
                             const std::string& what);

// Writes a depth image as a 16-bit PNG of round(metres / png_metres_per_unit), atomically. Throws
// Error if a depth is negative, not finite, or beyond 65535 units.
void write_depth_png(const DepthImage& depth, const std::filesystem::path& path,
                     double png_metres_per_unit = kDefaultPngMetresPerUnit);

// Reads a mask (PNG of any depth, or a numeric .npy of shape (H, W)): 1 where the pixel is
// non-zero. Throws Error "<path>: <why>" unless its size is width × height.
std::vector<std::uint8_t> read_mask(const std::filesystem::path& path, int width, int height);

// A mask from row-major values of shape (mask_height, mask_width): 1 where non-zero and not NaN.
// Throws Error "<what>: <why>" unless that is the depth image's width × height.
std::vector<std::uint8_t> mask_from_values(const std::vector<double>& values, int mask_height,
                                           int mask_width, int width, int height,
                                           const std::string& what);

// Writes a mask as an 8-bit PNG (255 on the object, 0 elsewhere), atomically.
void write_mask_png(const std::vector<std::uint8_t>& mask, int width, int height,
                    const std::filesystem::path& path);

}  // namespace graspecmf::camera
