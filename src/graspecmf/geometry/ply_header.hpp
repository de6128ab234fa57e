#pragma once
// The header of a PLY file: format, elements and their properties, checked against the file's
// size so that a reader never allocates for data the file cannot hold.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace graspecmf::geometry {

struct PlyProperty {
  std::string name;
  std::size_t size = 0;        // bytes of one binary value (of a list's items)
  std::size_t count_size = 0;  // bytes of a binary list's length; 0 for a scalar property
  bool floating = false;       // float / double values
  bool is_signed = false;      // values of a signed integer type (char, short, int)
  bool count_signed = false;   // a list length of a signed integer type
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  std::string format;  // "ascii", "binary_little_endian" or "binary_big_endian"
  std::vector<PlyElement> elements;
  std::size_t data_start = 0;  // offset of the first byte after "end_header\n"
};

// Parses the header at the start of head (the whole file or its first bytes) of a file of
// file_size bytes. Throws Error naming path if it is not a PLY header, a type is unknown, an
// element name is declared twice, or the declared elements need more bytes than the file has
// after its header (at least one byte per binary scalar, two characters per ASCII value).
PlyHeader read_ply_header(const std::filesystem::path& path, std::string_view head,
                          std::uintmax_t file_size);

}  // namespace graspecmf::geometry
