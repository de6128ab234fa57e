#include "graspecmf/geometry/ply_header.hpp"

#include <algorithm>
#include <sstream>

#include "graspecmf/core/error.hpp"

namespace graspecmf::geometry {
namespace {

// Bytes of one binary value of a PLY type; 0 for an unknown type.
std::size_t type_size(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" ||
      type == "float32") {
    return 4;
  }
  if (type == "double" || type == "float64") return 8;
  return 0;
}

bool is_floating(const std::string& type) {
  return type == "float" || type == "float32" || type == "double" || type == "float64";
}

bool is_signed_integer(const std::string& type) {
  return type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" ||
         type == "int32";
}

}  // namespace

PlyHeader read_ply_header(const std::filesystem::path& path, std::string_view head,
                          std::uintmax_t file_size) {
  const auto fail = [&](const std::string& why) { return Error(path.string() + ": " + why); };
  constexpr std::string_view kEnd = "end_header\n";
  const std::size_t end = head.find(kEnd);
  if (head.substr(0, 4) != "ply\n" || end == std::string_view::npos) {
    throw fail("not a PLY file");
  }
  // Header lines are text: "end_header" must start its own line, and control characters other
  // than tab and carriage return are refused (assimp's reader hangs on a vertical tab before it).
  const bool text =
      std::all_of(head.begin(), head.begin() + static_cast<std::ptrdiff_t>(end), [](char c) {
        const auto u = static_cast<unsigned char>(c);
        return u >= 0x20 || c == '\n' || c == '\r' || c == '\t';
      });
  if (!text || head[end - 1] != '\n') throw fail("the PLY header is not lines of text");
  PlyHeader header;
  header.data_start = end + kEnd.size();
  std::istringstream lines{std::string(head.substr(0, end))};
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      words >> header.format;
    } else if (keyword == "element") {
      PlyElement element;
      if (!(words >> element.name >> element.count)) throw fail("bad PLY element line: " + line);
      // Readers look elements up by name; assimp freed memory it did not own on a repeated one.
      if (std::any_of(header.elements.begin(), header.elements.end(),
                      [&](const PlyElement& e) { return e.name == element.name; })) {
        throw fail("the PLY element '" + element.name + "' is declared twice");
      }
      header.elements.push_back(element);
    } else if (keyword == "property") {
      if (header.elements.empty()) throw fail("PLY property before any element");
      PlyProperty property;
      std::string type;
      words >> type;
      if (type == "list") {
        std::string count_type;
        words >> count_type >> type;
        property.count_size = type_size(count_type);
        if (property.count_size == 0) throw fail("unknown PLY list count type " + count_type);
        if (is_floating(count_type)) throw fail("a PLY list count type must be an integer type");
        property.count_signed = is_signed_integer(count_type);
      }
      words >> property.name;
      property.size = type_size(type);
      if (property.size == 0) throw fail("unknown PLY property type " + type);
      property.floating = is_floating(type);
      property.is_signed = is_signed_integer(type);
      header.elements.back().properties.push_back(property);
    }
  }
  if (header.format != "ascii" && header.format != "binary_little_endian" &&
      header.format != "binary_big_endian") {
    throw fail("unknown PLY format '" + header.format + "'");
  }
  const long double body =
      file_size > header.data_start ? static_cast<long double>(file_size - header.data_start) : 0;
  long double needed = 0;
  for (const PlyElement& element : header.elements) {
    std::size_t per_item = 0;
    for (const PlyProperty& p : element.properties) {
      per_item += header.format == "ascii" ? 2 : (p.count_size > 0 ? p.count_size : p.size);
    }
    needed += static_cast<long double>(element.count) * static_cast<long double>(per_item);
  }
  if (needed > body) {
    throw fail("the PLY header declares more data than the file holds (" +
               std::to_string(static_cast<unsigned long long>(body)) +
               " bytes after the header); the file is truncated or damaged");
  }
  return header;
}

}  // namespace graspecmf::geometry
