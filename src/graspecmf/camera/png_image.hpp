#pragma once
// Single-channel PNG images: reading any grayscale or colour PNG as one channel of 8 or 16 bits
// (stb_image), and writing 8- or 16-bit grayscale PNGs (zlib), for depth images and masks.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace graspecmf::camera {

// A one-channel image, row-major from the top-left pixel.
struct GrayImage {
  int width = 0;
  int height = 0;
  int bits = 8;                       // 8 or 16: the range of the values
  std::vector<std::uint16_t> values;  // width × height values
};

// The PNG's first channel (grey, or red of a colour image) at its own bit depth. Throws Error
// "<path>: <why>" if the file is missing, too large, or not a readable PNG.
GrayImage read_png(const std::filesystem::path& path);

// Writes the image as an 8- or 16-bit grayscale PNG, atomically. Throws Error if the image's size
// does not match its values, a value exceeds its bit depth, or the file cannot be written.
void write_png(const GrayImage& image, const std::filesystem::path& path);

}  // namespace graspecmf::camera
