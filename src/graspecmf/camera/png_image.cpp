#include "graspecmf/camera/png_image.hpp"

#include <stb/stb_image.h>
#include <zlib.h>

#include <memory>
#include <string>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/input_file.hpp"

namespace graspecmf::camera {
namespace {

constexpr int kMaxSide = 1 << 14;  // pixels; far above any depth camera

void put_u32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<char>((v >> shift) & 0xff));
}

// Appends a PNG chunk: length, type, data and the CRC of type and data.
void put_chunk(std::string& out, const char* type, const std::string& data) {
  put_u32(out, static_cast<std::uint32_t>(data.size()));
  const std::string body = std::string(type, 4) + data;
  out += body;
  put_u32(out, static_cast<std::uint32_t>(crc32(0L, reinterpret_cast<const Bytef*>(body.data()),
                                                static_cast<uInt>(body.size()))));
}

}  // namespace

GrayImage read_png(const std::filesystem::path& path) {
  const std::string bytes = read_input_file(path);
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = static_cast<int>(bytes.size());
  int width = 0, height = 0, channels = 0;
  if (bytes.size() > static_cast<std::size_t>(INT32_MAX) ||
      !stbi_info_from_memory(data, size, &width, &height, &channels)) {
    throw Error(path.string() + ": not a readable PNG image");
  }
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
    throw Error(path.string() + ": image size " + std::to_string(width) + " × " +
                std::to_string(height) + " is out of range");
  }
  GrayImage image;
  image.width = width;
  image.height = height;
  image.bits = stbi_is_16_bit_from_memory(data, size) ? 16 : 8;
  const auto pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  image.values.resize(pixels);
  if (image.bits == 16) {
    std::unique_ptr<stbi_us, void (*)(void*)> decoded(
        stbi_load_16_from_memory(data, size, &width, &height, &channels, 1), stbi_image_free);
    if (!decoded) throw Error(path.string() + ": " + stbi_failure_reason());
    std::copy(decoded.get(), decoded.get() + pixels, image.values.begin());
  } else {
    std::unique_ptr<stbi_uc, void (*)(void*)> decoded(
        stbi_load_from_memory(data, size, &width, &height, &channels, 1), stbi_image_free);
    if (!decoded) throw Error(path.string() + ": " + stbi_failure_reason());
    std::copy(decoded.get(), decoded.get() + pixels, image.values.begin());
  }
  return image;
}

void write_png(const GrayImage& image, const std::filesystem::path& path) {
  if (image.bits != 8 && image.bits != 16) throw Error("a PNG image has 8 or 16 bits per value");
  if (image.width < 1 || image.height < 1 || image.width > kMaxSide || image.height > kMaxSide ||
      image.values.size() != static_cast<std::size_t>(image.width) * image.height) {
    throw Error("the image's size does not match its values");
  }
  const int bytes_per_value = image.bits / 8;
  std::string raw;
  raw.reserve(image.values.size() * bytes_per_value + image.height);
  for (int row = 0; row < image.height; ++row) {
    raw.push_back(0);  // filter: none
    for (int col = 0; col < image.width; ++col) {
      const std::uint16_t v = image.values[static_cast<std::size_t>(row) * image.width + col];
      if (image.bits == 8 && v > 255) throw Error("a value of an 8-bit image exceeds 255");
      if (image.bits == 16) raw.push_back(static_cast<char>(v >> 8));
      raw.push_back(static_cast<char>(v & 0xff));
    }
  }
  uLongf packed_size = compressBound(static_cast<uLong>(raw.size()));
  std::string packed(packed_size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(packed.data()), &packed_size,
                reinterpret_cast<const Bytef*>(raw.data()), static_cast<uLong>(raw.size()),
                Z_BEST_SPEED) != Z_OK) {
    throw Error("cannot compress the PNG image");
  }
  packed.resize(packed_size);
  std::string header;
  put_u32(header, static_cast<std::uint32_t>(image.width));
  put_u32(header, static_cast<std::uint32_t>(image.height));
  header += {static_cast<char>(image.bits), 0, 0, 0, 0};  // grey, deflate, no filter, no interlace
  std::string file = "\x89PNG\r\n\x1a\n";
  put_chunk(file, "IHDR", header);
  put_chunk(file, "IDAT", packed);
  put_chunk(file, "IEND", "");
  write_file_atomically(path, file);
}

}  // namespace graspecmf::camera
