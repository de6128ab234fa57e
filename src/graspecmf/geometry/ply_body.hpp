#pragma once
// The data of a PLY file (ascii, binary little- or big-endian) after its header: the values of
// chosen properties, read with every length checked against the bytes that are left.

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "graspecmf/geometry/ply_header.hpp"
#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

// One property's values for every item of its element, as doubles (exact for every PLY type).
// A scalar property has one value per item and no starts; a list property's item i holds
// values[starts[i], starts[i + 1]).
struct PlyColumn {
  std::vector<double> values;
  std::vector<std::size_t> starts;
};

// Reads the data of the PLY file held in bytes, whose header is header, and returns the columns of
// the properties named in wanted as {element, property} pairs, in that order. Throws Error
// "<path>: <why>" if a wanted property is not declared, the data ends early, an ascii value is not
// a number (an integer for an integer type), a list length is negative, or anything but whitespace
// follows the last item.
std::vector<PlyColumn> read_ply_columns(
    const std::filesystem::path& path, std::string_view bytes, const PlyHeader& header,
    const std::vector<std::pair<std::string, std::string>>& wanted);

// The property named name of the element named element, or nullptr if header declares none.
const PlyProperty* find_ply_property(const PlyHeader& header, const std::string& element,
                                     const std::string& name);

// The wanted-list names of the vertices' x, y and z; throws Error "<path>: <why>" unless header
// declares all three as scalar properties of an element named vertex.
std::vector<std::pair<std::string, std::string>> ply_xyz_names(const std::filesystem::path& path,
                                                               const PlyHeader& header);

// The points whose x, y and z are the first three of columns (as read for ply_xyz_names).
std::vector<Vec3> ply_points(const std::vector<PlyColumn>& columns);

}  // namespace graspecmf::geometry
