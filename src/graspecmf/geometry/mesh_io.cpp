#include "graspecmf/geometry/mesh_io.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/input_file.hpp"
#include "graspecmf/core/number_text.hpp"
#include "graspecmf/geometry/ply_body.hpp"
#include "graspecmf/geometry/ply_header.hpp"

namespace graspecmf::geometry {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail_read(const fs::path& path, const std::string& why) {
  throw Error("cannot read " + path.string() + ": " + why);
}

// Calls read(), giving an Error it throws ("<path>: <why>") the mesh reader's "cannot read "
// prefix.
template <typename Read>
auto with_read_prefix(const Read& read) {
  try {
    return read();
  } catch (const Error& e) {
    throw Error(std::string("cannot read ") + e.what());
  }
}

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

// Splits a line at blanks into tokens (reusing the vector's storage).
void split_tokens(std::string_view line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_blank(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
}

bool parse_index(std::string_view s) {
  if (!s.empty() && s.front() == '-') s.remove_prefix(1);
  if (s.empty()) return false;
  bool nonzero = false;
  for (const char c : s) {
    if (c < '0' || c > '9') return false;
    nonzero = nonzero || c != '0';
  }
  return nonzero;
}

// One face corner: v, v/vt, v//vn or v/vt/vn with non-zero integers.
bool valid_face_corner(std::string_view token) {
  const std::size_t s1 = token.find('/');
  if (s1 == std::string_view::npos) return parse_index(token);
  if (!parse_index(token.substr(0, s1))) return false;
  const std::string_view rest = token.substr(s1 + 1);
  const std::size_t s2 = rest.find('/');
  if (s2 == std::string_view::npos) return parse_index(rest);
  return (s2 == 0 || parse_index(rest.substr(0, s2))) && parse_index(rest.substr(s2 + 1));
}

bool known_obj_keyword(std::string_view k) {
  static constexpr std::array<std::string_view, 14> kKeywords = {
      "v", "vt", "vn", "vp", "vw", "f", "l", "p", "g", "o", "s", "t", "usemtl", "mtllib"};
  return std::find(kKeywords.begin(), kKeywords.end(), k) != kKeywords.end();
}

// Problem with one OBJ statement, or empty if fine. Vertex coordinates are appended to vertices
// and the triangle count of a face to triangles.
std::string check_obj_statement(const std::vector<std::string_view>& tokens, bool last_unterminated,
                                std::vector<Vec3>& vertices, std::size_t& triangles) {
  const std::string_view key = tokens[0];
  const std::size_t args = tokens.size() - 1;
  if (key == "v" || key == "vn" || key == "vt") {
    std::array<double, 7> x{};
    const std::size_t lo = key == "vt" ? 1 : 3;
    const std::size_t hi = key == "v" ? 7 : 3;
    if (args < lo || args > hi) {
      return "'" + std::string(key) + "' needs " + std::to_string(lo) +
             (lo == hi ? "" : " to " + std::to_string(hi)) + " numbers, found " +
             std::to_string(args);
    }
    for (std::size_t i = 0; i < args; ++i) {
      if (!parse_number(tokens[i + 1], x[i])) {
        return "'" + std::string(tokens[i + 1]) + "' is not a number";
      }
    }
    if (key == "v") {
      if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) {
        return "vertex " + std::to_string(vertices.size() + 1) + " has a non-finite coordinate";
      }
      vertices.emplace_back(x[0], x[1], x[2]);
    }
    return {};
  }
  if (key == "f") {
    if (args < 3) return "face with " + std::to_string(args) + " vertices (at least 3 needed)";
    for (std::size_t i = 1; i <= args; ++i) {
      if (!valid_face_corner(tokens[i])) {
        return "face corner '" + std::string(tokens[i]) + "' is not a valid vertex reference";
      }
    }
    triangles += args - 2;
    return {};
  }
  if (last_unterminated && key.front() != '#' && !known_obj_keyword(key)) {
    return "unknown statement '" + std::string(key) + "'";
  }
  return {};
}

struct ObjScan {
  std::vector<Vec3> vertices;          // coordinates of the `v` statements, in file order
  std::size_t expected_triangles = 0;  // Σ (corners − 2) over the `f` statements
};

// Checks every line of an OBJ text and reads the vertex coordinates exactly (see mesh_io.hpp).
ObjScan scan_obj_text(const std::string& text, const fs::path& path) {
  if (text.find('\0') != std::string::npos) fail_read(path, "not a text OBJ file (NUL bytes)");
  ObjScan scan;
  std::vector<std::string_view> tokens;
  std::size_t line_number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = pos;
    while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
    const bool terminated = end < text.size();
    ++line_number;
    split_tokens(std::string_view(text).substr(pos, end - pos), tokens);
    pos = end;
    if (pos < text.size() && text[pos] == '\r') ++pos;  // \r, \r\n and \n end a line
    if (pos < text.size() && text[pos] == '\n') ++pos;
    if (tokens.empty() || tokens[0].front() == '#') continue;
    const std::string problem =
        check_obj_statement(tokens, !terminated, scan.vertices, scan.expected_triangles);
    if (problem.empty()) continue;
    if (!terminated) {
      fail_read(path, "the file is truncated: its last line (" + std::to_string(line_number) +
                          ") has no newline and is incomplete: " + problem);
    }
    fail_read(path, "line " + std::to_string(line_number) + ": " + problem);
  }
  return scan;
}

TriangleMesh read_obj(const fs::path& path) {
  const std::string text = with_read_prefix([&] { return read_input_file(path); });
  ObjScan scan = scan_obj_text(text, path);
  if (scan.expected_triangles == 0) {
    fail_read(path, "no faces (" + std::to_string(scan.vertices.size()) +
                        " vertices; an empty or truncated file?)");
  }

  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, "", config)) fail_read(path, first_line(reader.Error()));
  const std::string& warning = reader.Warning();
  if (warning.find("Vertex indices out of bounds") != std::string::npos ||
      warning.find("invalid vertex index") != std::string::npos) {
    fail_read(path, "a face refers to a vertex beyond the " + std::to_string(scan.vertices.size()) +
                        " vertices of the file");
  }

  const std::vector<tinyobj::real_t>& coords = reader.GetAttrib().vertices;
  if (coords.size() != 3 * scan.vertices.size()) {
    fail_read(path, "OBJ vertex count mismatch (" + std::to_string(coords.size() / 3) +
                        " from tinyobjloader, " + std::to_string(scan.vertices.size()) +
                        " in the text)");
  }
  // The exact coordinates replace tinyobjloader's (which are often off in the last bits); a larger
  // difference would mean that the two readings disagree about which line is which vertex.
  for (std::size_t i = 0; i < scan.vertices.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const double exact = scan.vertices[i][k];
      const double tiny = static_cast<double>(coords[3 * i + k]);
      if (!(std::abs(tiny - exact) <= 1e-6 * std::abs(exact) + 1e-300)) {
        fail_read(path, "vertex " + std::to_string(i + 1) + " was read inconsistently");
      }
    }
  }

  TriangleMesh mesh;
  mesh.vertices = std::move(scan.vertices);
  const long long n = static_cast<long long>(mesh.vertices.size());
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const std::vector<tinyobj::index_t>& indices = shape.mesh.indices;
    std::size_t offset = 0;
    for (const unsigned int corners : shape.mesh.num_face_vertices) {
      if (corners != 3 || offset + 3 > indices.size()) {
        fail_read(path, "tinyobjloader returned a face with " + std::to_string(corners) +
                            " corners after triangulation");
      }
      Triangle tri{};
      for (std::size_t k = 0; k < 3; ++k) {
        const long long v = indices[offset + k].vertex_index;
        if (v < 0 || v >= n) {
          fail_read(path, "a face refers to vertex " + std::to_string(v >= 0 ? v + 1 : v) +
                              " but the file has " + std::to_string(n) + " vertices");
        }
        tri[k] = static_cast<std::uint32_t>(v);
      }
      mesh.triangles.push_back(tri);
      offset += 3;
    }
  }
  if (mesh.triangles.size() != scan.expected_triangles) {
    fail_read(path, std::to_string(scan.expected_triangles) +
                        " triangles expected from the faces but " +
                        std::to_string(mesh.triangles.size()) +
                        " were produced (a polygon could not be triangulated)");
  }
  return mesh;
}

// ---- polygons ----

// Appends the polygon face with the given mesh vertex indices (all valid) as a fan of triangles
// from its first corner: exact for a convex polygon; a polygon where a fan triangle faces against
// the polygon's normal (concave) is refused. Faces of fewer than 3 corners carry no surface and
// are skipped.
void add_polygon(const fs::path& path, const std::vector<std::uint32_t>& corners,
                 TriangleMesh& mesh) {
  const std::size_t n = corners.size();
  if (n < 3) return;
  const auto corner = [&](std::size_t k) { return mesh.vertices[corners[k]]; };
  Vec3 normal = Vec3::Zero();  // Newell's normal of the polygon
  for (std::size_t k = 0; k < n; ++k) normal += corner(k).cross(corner((k + 1) % n));
  for (std::size_t k = 1; k + 1 < n; ++k) {
    if ((corner(k) - corner(0)).cross(corner(k + 1) - corner(0)).dot(normal) < 0) {
      fail_read(path, "a face is a polygon of " + std::to_string(n) +
                          " corners that a fan from its first corner cannot split (concave; "
                          "triangulate the mesh in a mesh editor first)");
    }
    mesh.triangles.push_back({corners[0], corners[k], corners[k + 1]});
  }
}

// ---- PLY ----

// Reads a PLY mesh (ascii or binary of either byte order): scalar x, y, z of the vertices and the
// vertex_indices (or vertex_index) lists of the faces; other elements and properties are skipped.
TriangleMesh read_ply_mesh(const fs::path& path) {
  return with_read_prefix([&] {
    const std::string bytes = read_input_file(path);
    const PlyHeader header = read_ply_header(path, bytes, bytes.size());
    const auto fail = [&](const std::string& why) { return Error(path.string() + ": " + why); };
    auto names = ply_xyz_names(path, header);
    std::string indices = "vertex_indices";
    if (find_ply_property(header, "face", indices) == nullptr) indices = "vertex_index";
    const PlyProperty* faces = find_ply_property(header, "face", indices);
    if (faces == nullptr || faces->count_size == 0) {
      throw fail("the PLY file has no faces (no list property face.vertex_indices)");
    }
    names.emplace_back("face", indices);
    const std::vector<PlyColumn> columns = read_ply_columns(path, bytes, header, names);
    TriangleMesh mesh;
    mesh.vertices = ply_points(columns);
    const PlyColumn& face = columns[3];
    std::vector<std::uint32_t> corners;
    for (std::size_t f = 0; f + 1 < face.starts.size(); ++f) {
      corners.clear();
      for (std::size_t k = face.starts[f]; k < face.starts[f + 1]; ++k) {
        const double v = face.values[k];
        if (!(v >= 0 && v < static_cast<double>(mesh.vertices.size()) && std::floor(v) == v)) {
          std::ostringstream why;
          why << "face " << f << " refers to vertex " << v << " but the file has "
              << mesh.vertices.size() << " vertices";
          throw fail(why.str());
        }
        corners.push_back(static_cast<std::uint32_t>(v));
      }
      add_polygon(path, corners, mesh);
    }
    return mesh;
  });
}

// ---- STL and glTF through assimp ----

TriangleMesh read_with_assimp(const fs::path& path) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path.string(), aiProcess_JoinIdenticalVertices |
                                                              aiProcess_PreTransformVertices |
                                                              aiProcess_ValidateDataStructure);
  if (scene == nullptr) fail_read(path, first_line(importer.GetErrorString()));
  TriangleMesh mesh;
  std::vector<std::uint32_t> corners;
  for (unsigned int m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& part = *scene->mMeshes[m];
    const auto offset = static_cast<std::uint32_t>(mesh.vertices.size());
    for (unsigned int i = 0; i < part.mNumVertices; ++i) {
      const aiVector3D& v = part.mVertices[i];
      mesh.vertices.emplace_back(v.x, v.y, v.z);
    }
    for (unsigned int f = 0; f < part.mNumFaces; ++f) {
      const aiFace& face = part.mFaces[f];
      corners.clear();
      for (unsigned int k = 0; k < face.mNumIndices; ++k) {
        if (face.mIndices[k] >= part.mNumVertices) {
          fail_read(path, "a face refers to vertex " + std::to_string(face.mIndices[k]) +
                              " of a part with " + std::to_string(part.mNumVertices) + " vertices");
        }
        corners.push_back(offset + face.mIndices[k]);
      }
      add_polygon(path, corners, mesh);
    }
  }
  return mesh;
}

// ---- welding ----

struct PositionHash {
  std::size_t operator()(const std::array<double, 3>& p) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (const double x : p) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &x, sizeof bits);
      h ^= bits + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    }
    return static_cast<std::size_t>(h);
  }
};

// Merges vertices at bit-identical positions (−0 = +0), keeping the first of each; drops the
// triangles that the merge (or the file) made degenerate by repeating a vertex.
void weld(TriangleMesh& mesh) {
  std::unordered_map<std::array<double, 3>, std::uint32_t, PositionHash> first;
  first.reserve(mesh.vertices.size());
  std::vector<std::uint32_t> remap(mesh.vertices.size());
  std::vector<Vec3> unique;
  unique.reserve(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& v = mesh.vertices[i];
    const std::array<double, 3> key{v.x() + 0.0, v.y() + 0.0, v.z() + 0.0};
    const auto [it, inserted] = first.try_emplace(key, static_cast<std::uint32_t>(unique.size()));
    if (inserted) unique.push_back(v);
    remap[i] = it->second;
  }
  if (unique.size() != mesh.vertices.size()) {
    mesh.vertices = std::move(unique);
    for (Triangle& tri : mesh.triangles) {
      for (std::uint32_t& v : tri) v = remap[v];
    }
  }
  mesh.triangles.erase(std::remove_if(mesh.triangles.begin(), mesh.triangles.end(),
                                      [](const Triangle& t) {
                                        return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
                                      }),
                       mesh.triangles.end());
}

// ---- writers ----

void append_number(std::string& out, double x) {
  char buffer[32];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::general, 17);
  out.append(buffer, result.ptr);
}

std::string obj_text(const TriangleMesh& mesh) {
  std::string out = "# graspecmf mesh: " + std::to_string(mesh.vertices.size()) + " vertices, " +
                    std::to_string(mesh.triangles.size()) + " triangles\n";
  out.reserve(out.size() + mesh.vertices.size() * 64 + mesh.triangles.size() * 24);
  for (const Vec3& v : mesh.vertices) {
    out += "v ";
    append_number(out, v.x());
    out += ' ';
    append_number(out, v.y());
    out += ' ';
    append_number(out, v.z());
    out += '\n';
  }
  for (const Triangle& t : mesh.triangles) {
    out += "f " + std::to_string(t[0] + 1) + ' ' + std::to_string(t[1] + 1) + ' ' +
           std::to_string(t[2] + 1) + '\n';
  }
  return out;
}

void append_le(std::string& out, std::uint64_t bits, std::size_t size) {
  for (std::size_t i = 0; i < size; ++i) out += static_cast<char>((bits >> (8 * i)) & 0xffU);
}

std::string ply_bytes(const TriangleMesh& mesh) {
  std::string out =
      "ply\nformat binary_little_endian 1.0\ncomment graspecmf mesh\nelement vertex " +
      std::to_string(mesh.vertices.size()) +
      "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
      std::to_string(mesh.triangles.size()) +
      "\nproperty list uchar uint vertex_indices\nend_header\n";
  out.reserve(out.size() + mesh.vertices.size() * 24 + mesh.triangles.size() * 13);
  for (const Vec3& v : mesh.vertices) {
    for (int k = 0; k < 3; ++k) {
      std::uint64_t bits = 0;
      const double x = v[k];
      std::memcpy(&bits, &x, sizeof bits);
      append_le(out, bits, 8);
    }
  }
  for (const Triangle& t : mesh.triangles) {
    out += static_cast<char>(3);
    for (const std::uint32_t v : t) append_le(out, v, 4);
  }
  return out;
}

}  // namespace

TriangleMesh read_mesh(const fs::path& path) {
  with_read_prefix([&] { check_input_file(path); });
  const std::string ext = lower_extension(path);
  TriangleMesh mesh;
  if (ext == ".obj") {
    mesh = read_obj(path);
  } else if (ext == ".ply") {
    mesh = read_ply_mesh(path);
  } else if (ext == ".stl" || ext == ".glb" || ext == ".gltf") {
    mesh = read_with_assimp(path);
  } else {
    fail_read(path,
              "unsupported extension '" + ext + "' (expected .obj, .stl, .ply, .glb or .gltf)");
  }
  weld(mesh);
  validate_mesh(mesh, "cannot read " + path.string());
  return mesh;
}

void write_mesh(const TriangleMesh& mesh, const fs::path& path) {
  const std::string ext = lower_extension(path);
  if (ext != ".obj" && ext != ".ply") {
    throw Error("cannot write " + path.string() + ": unsupported extension '" + ext +
                "' (expected .obj or .ply)");
  }
  validate_mesh(mesh, "cannot write " + path.string());
  const std::string bytes = ext == ".obj" ? obj_text(mesh) : ply_bytes(mesh);
  write_file_atomically(path, bytes);
}

}  // namespace graspecmf::geometry
