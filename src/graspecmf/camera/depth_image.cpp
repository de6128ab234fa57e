#include "graspecmf/camera/depth_image.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "graspecmf/camera/png_image.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/input_file.hpp"
#include "graspecmf/core/npy.hpp"

namespace graspecmf::camera {
namespace {

std::string size_text(int width, int height) {
  return std::to_string(width) + " × " + std::to_string(height);
}

// An (H, W) .npy array; throws Error "<path>: <why>" for another shape.
NpyArray read_image_npy(const std::filesystem::path& path) {
  NpyArray array = parse_npy(read_input_file(path), path.string());
  if (array.shape.size() != 2 || array.shape[0] == 0 || array.shape[1] == 0 ||
      array.shape[0] > (1u << 14) || array.shape[1] > (1u << 14)) {
    throw Error(path.string() + ": expected an image array of shape (height, width)");
  }
  return array;
}

}  // namespace

DepthImage read_depth_image(const std::filesystem::path& path, double png_metres_per_unit) {
  if (!std::isfinite(png_metres_per_unit) || png_metres_per_unit <= 0.0) {
    throw Error("the depth unit must be a positive number of metres");
  }
  const std::string extension = lower_extension(path);
  DepthImage depth;
  if (extension == ".png") {
    const GrayImage image = read_png(path);
    if (image.bits != 16) {
      throw Error(path.string() +
                  ": an 8-bit PNG cannot hold depth; expected a 16-bit PNG (millimetres)");
    }
    depth.width = image.width;
    depth.height = image.height;
    depth.metres.reserve(image.values.size());
    for (const std::uint16_t v : image.values) {
      depth.metres.push_back(static_cast<float>(v * png_metres_per_unit));
    }
  } else if (extension == ".npy") {
    const NpyArray array = read_image_npy(path);
    // Integer arrays are in the PNG's unit, as a depth PNG read with NumPy would be.
    depth = depth_from_values(array.values, static_cast<int>(array.shape[0]),
                              static_cast<int>(array.shape[1]),
                              array.integral ? png_metres_per_unit : 1.0, path.string());
  } else {
    throw Error(path.string() + ": a depth image must be a 16-bit .png or a .npy array");
  }
  return depth;
}

DepthImage depth_from_values(const std::vector<double>& values, int height, int width, double scale,
                             const std::string& what) {
  if (height <= 0 || width <= 0 ||
      values.size() != static_cast<std::size_t>(height) * static_cast<std::size_t>(width)) {
    throw Error(what + ": expected a depth image of shape (height, width)");
  }
  DepthImage depth;
  depth.height = height;
  depth.width = width;
  depth.metres.reserve(values.size());
  for (const double v : values) {
    if (v < 0.0) throw Error(what + ": a depth is negative (" + std::to_string(v) + ")");
    depth.metres.push_back(std::isfinite(v) ? static_cast<float>(v * scale) : 0.0f);
  }
  return depth;
}

void write_depth_png(const DepthImage& depth, const std::filesystem::path& path,
                     double png_metres_per_unit) {
  GrayImage image;
  image.width = depth.width;
  image.height = depth.height;
  image.bits = 16;
  image.values.reserve(depth.metres.size());
  for (const float metres : depth.metres) {
    const double units = std::round(metres / png_metres_per_unit);
    if (!std::isfinite(units) || units < 0.0 || units > 65535.0) {
      throw Error("cannot write a depth of " + std::to_string(metres) + " m to a 16-bit PNG");
    }
    image.values.push_back(static_cast<std::uint16_t>(units));
  }
  write_png(image, path);
}

std::vector<std::uint8_t> read_mask(const std::filesystem::path& path, int width, int height) {
  if (lower_extension(path) == ".npy") {
    const NpyArray array = read_image_npy(path);
    return mask_from_values(array.values, static_cast<int>(array.shape[0]),
                            static_cast<int>(array.shape[1]), width, height, path.string());
  }
  const GrayImage image = read_png(path);
  return mask_from_values(std::vector<double>(image.values.begin(), image.values.end()),
                          image.height, image.width, width, height, path.string());
}

std::vector<std::uint8_t> mask_from_values(const std::vector<double>& values, int mask_height,
                                           int mask_width, int width, int height,
                                           const std::string& what) {
  if (mask_width != width || mask_height != height ||
      values.size() != static_cast<std::size_t>(std::max(width, 0)) *
                           static_cast<std::size_t>(std::max(height, 0))) {
    throw Error(what + ": the mask is " + size_text(mask_width, mask_height) +
                " pixels but the depth image is " + size_text(width, height));
  }
  std::vector<std::uint8_t> mask;
  mask.reserve(values.size());
  for (const double v : values) mask.push_back(v != 0.0 && !std::isnan(v));
  return mask;
}

void write_mask_png(const std::vector<std::uint8_t>& mask, int width, int height,
                    const std::filesystem::path& path) {
  GrayImage image;
  image.width = width;
  image.height = height;
  image.values.reserve(mask.size());
  for (const std::uint8_t v : mask) image.values.push_back(v != 0 ? 255 : 0);
  write_png(image, path);
}

}  // namespace graspecmf::camera
