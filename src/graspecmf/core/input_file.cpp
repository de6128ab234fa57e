#include "graspecmf/core/input_file.hpp"

#include <cctype>
#include <fstream>

#include "graspecmf/core/error.hpp"

namespace graspecmf {
namespace fs = std::filesystem;
namespace {

// max_bytes in words: "1 GiB", "64 MiB" or a byte count.
std::string size_words(std::uintmax_t max_bytes) {
  if (max_bytes % (1U << 30) == 0) return std::to_string(max_bytes >> 30) + " GiB";
  if (max_bytes % (1U << 20) == 0) return std::to_string(max_bytes >> 20) + " MiB";
  return std::to_string(max_bytes) + " bytes";
}

}  // namespace

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::uintmax_t check_input_file(const fs::path& path, std::uintmax_t max_bytes) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error(path.string() + ": no such file");
  if (!fs::is_regular_file(path, ec)) throw Error(path.string() + ": not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw Error(path.string() + ": the file size cannot be read");
  if (size > max_bytes) {
    throw Error(path.string() + ": the file has " + std::to_string(size) + " bytes; files over " +
                size_words(max_bytes) + " are refused here");
  }
  return size;
}

std::string read_input_file(const fs::path& path, std::uintmax_t max_bytes) {
  const std::uintmax_t size = check_input_file(path, max_bytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": the file cannot be opened");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (static_cast<std::size_t>(in.gcount()) != bytes.size()) {
    throw Error(path.string() + ": reading the file failed");
  }
  return bytes;
}

}  // namespace graspecmf
