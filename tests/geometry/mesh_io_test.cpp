#include "graspecmf/geometry/mesh_io.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/input_file.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"
#include "test_meshes.hpp"

namespace graspecmf::geometry {
namespace {

using namespace graspecmf::geometry::testing;

// The Error message of read_mesh(path), or "" if it read without error.
std::string read_error(const fs::path& path) {
  try {
    read_mesh(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

void expect_same_mesh(const TriangleMesh& a, const TriangleMesh& b) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    // Bitwise: the round trip must not move a vertex by a single ulp.
    ASSERT_EQ(std::memcmp(a.vertices[i].data(), b.vertices[i].data(), 3 * sizeof(double)), 0)
        << "vertex " << i;
  }
  EXPECT_EQ(a.triangles, b.triangles);
}

// A mesh whose coordinates need all 17 digits: the metric mug, jittered by random amounts over
// many magnitudes.
TriangleMesh awkward_mesh() {
  TriangleMesh mesh = scaled(read_mesh(kMugPath), kMugScale);
  Rng rng(7);
  for (Vec3& v : mesh.vertices) {
    for (int k = 0; k < 3; ++k)
      v[k] += rng.normal() * std::pow(10.0, -static_cast<double>(rng.index(12)));
  }
  mesh.vertices[0] = Vec3(1e-300, -3.5e300, std::numeric_limits<double>::denorm_min());
  return mesh;
}

std::string cube_ascii_stl() {
  const TriangleMesh cube = make_unit_cube();
  std::string text = "solid cube\n";
  for (std::size_t t = 0; t < cube.triangles.size(); ++t) {
    const Vec3 n = triangle_normal(cube, t);
    text += "  facet normal " + std::to_string(n.x()) + " " + std::to_string(n.y()) + " " +
            std::to_string(n.z()) + "\n    outer loop\n";
    for (const std::uint32_t v : cube.triangles[t]) {
      const Vec3& x = cube.vertices[v];
      text += "      vertex " + std::to_string(x.x()) + " " + std::to_string(x.y()) + " " +
              std::to_string(x.z()) + "\n";
    }
    text += "    endloop\n  endfacet\n";
  }
  return text + "endsolid cube\n";
}

TEST(ReadMesh, MugHasTheDocumentedCounts) {
  const TriangleMesh mug = read_mesh(kMugPath);
  EXPECT_EQ(mug.vertices.size(), 1167u);
  EXPECT_EQ(mug.triangles.size(), 2334u);
  // Scaled bounding box from the sample's README.
  const BoundingBox box = bounding_box(scaled(mug, kMugScale));
  EXPECT_NEAR(box.min.x(), -0.0381, 1e-4);
  EXPECT_NEAR(box.min.y(), -0.0630, 1e-4);
  EXPECT_NEAR(box.min.z(), 0.0514, 1e-4);
  EXPECT_NEAR(box.max.x(), 0.0381, 1e-4);
  EXPECT_NEAR(box.max.y(), 0.0380, 1e-4);
  EXPECT_NEAR(box.max.z(), 0.1525, 1e-4);
}

TEST(ReadMesh, ObjCoordinatesAreCorrectlyRounded) {
  // First line of the mug: "v -13.0854586804571 -207.403998976758 346.056676460709".
  const TriangleMesh mug = read_mesh(kMugPath);
  EXPECT_EQ(mug.vertices[0].x(), -13.0854586804571);
  EXPECT_EQ(mug.vertices[0].y(), -207.403998976758);
  EXPECT_EQ(mug.vertices[0].z(), 346.056676460709);
  EXPECT_EQ(mug.triangles[0], (Triangle{0, 2, 1}));  // "f 1 3 2"
}

TEST(WriteMesh, ObjRoundTripIsExact) {
  ScratchDir dir;
  const TriangleMesh mesh = awkward_mesh();
  write_mesh(mesh, dir / "m.obj");
  expect_same_mesh(read_mesh(dir / "m.obj"), mesh);
  EXPECT_EQ(dir.num_files(), 1u);
}

TEST(WriteMesh, PlyRoundTripIsExact) {
  ScratchDir dir;
  const TriangleMesh mesh = awkward_mesh();
  write_mesh(mesh, dir / "m.ply");
  expect_same_mesh(read_mesh(dir / "m.ply"), mesh);
  const std::string bytes = read_file(dir / "m.ply");
  EXPECT_NE(bytes.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_NE(bytes.find("property double x"), std::string::npos);
  EXPECT_EQ(dir.num_files(), 1u);
}

TEST(WriteMesh, MugRoundTripsThroughBothFormats) {
  ScratchDir dir;
  const TriangleMesh mug = read_mesh(kMugPath);
  write_mesh(mug, dir / "mug.OBJ");  // extensions are case-insensitive
  write_mesh(mug, dir / "mug.ply");
  expect_same_mesh(read_mesh(dir / "mug.OBJ"), mug);
  expect_same_mesh(read_mesh(dir / "mug.ply"), mug);
}

TEST(WriteMesh, OverwritesAnExistingFile) {
  ScratchDir dir;
  write_mesh(make_unit_cube(), dir / "m.obj");
  write_mesh(make_box(Vec3::Zero(), Vec3(1, 2, 3)), dir / "m.obj");
  EXPECT_EQ(read_mesh(dir / "m.obj").vertices[7], Vec3(1, 2, 3));
  EXPECT_EQ(dir.num_files(), 1u);
}

TEST(ReadMesh, GripperStlReadsWelded) {
  const TriangleMesh gripper = read_mesh(kGripperPath);
  EXPECT_GT(gripper.triangles.size(), 0u);
  // STL repeats every corner; welding shares them (a closed mesh has about V ≈ F / 2).
  EXPECT_LT(gripper.vertices.size(), gripper.triangles.size());
  EXPECT_TRUE(analyze_topology(gripper).watertight);
}

TEST(ReadMesh, AsciiStlCubeWeldsToEightVertices) {
  ScratchDir dir;
  write_file(dir / "cube.stl", cube_ascii_stl());
  const TriangleMesh cube = read_mesh(dir / "cube.stl");
  EXPECT_EQ(cube.vertices.size(), 8u);
  EXPECT_EQ(cube.triangles.size(), 12u);
  const MeshTopology topo = analyze_topology(cube);
  EXPECT_TRUE(topo.consistently_oriented);
  EXPECT_EQ(topo.genus, 0);
}

TEST(ReadMesh, BinaryStlCubeWeldsToEightVertices) {
  ScratchDir dir;
  const TriangleMesh cube = make_unit_cube();
  std::string bytes(80, '\0');
  const auto put_u32 = [&](std::uint32_t x) {
    for (int i = 0; i < 4; ++i) bytes += static_cast<char>((x >> (8 * i)) & 0xff);
  };
  const auto put_f32 = [&](double x) {
    const float f = static_cast<float>(x);
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, 4);
    put_u32(bits);
  };
  put_u32(static_cast<std::uint32_t>(cube.triangles.size()));
  for (std::size_t t = 0; t < cube.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) put_f32(triangle_normal(cube, t)[k]);
    for (const std::uint32_t v : cube.triangles[t]) {
      for (int k = 0; k < 3; ++k) put_f32(cube.vertices[v][k]);
    }
    bytes += std::string(2, '\0');
  }
  write_file(dir / "cube.STL", bytes);
  const TriangleMesh read = read_mesh(dir / "cube.STL");
  EXPECT_EQ(read.vertices.size(), 8u);
  EXPECT_EQ(read.triangles.size(), 12u);
  EXPECT_TRUE(analyze_topology(read).consistently_oriented);
}

TEST(ReadMesh, BinaryDoublePlyWithExtraPropertiesAndQuads) {
  // Other vertex properties around double x/y/z, int indices, a quad (split into two triangles).
  ScratchDir dir;
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\ncomment test\nelement vertex 4\nproperty float nx\n"
      "property double x\nproperty double y\nproperty double z\nproperty uchar red\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::vector<Vec3> corners = {Vec3(0.1, 0.2, 0.3), Vec3(1.0 / 3.0, 0, 0), Vec3(1, 1, 0),
                                     Vec3(0, 1, -1e-17)};
  for (const Vec3& v : corners) {
    bytes += std::string(4, '\x7f');  // nx
    for (int k = 0; k < 3; ++k) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &v[k], 8);
      for (int i = 0; i < 8; ++i) bytes += static_cast<char>((bits >> (8 * i)) & 0xff);
    }
    bytes += '\x05';  // red
  }
  bytes += '\x04';
  for (const int id : {0, 1, 2, 3}) bytes += std::string{static_cast<char>(id), 0, 0, 0};
  write_file(dir / "quad.ply", bytes);
  const TriangleMesh mesh = read_mesh(dir / "quad.ply");
  ASSERT_EQ(mesh.vertices.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(mesh.vertices[i], corners[i]) << i;
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_NEAR(surface_area(mesh), surface_area(TriangleMesh{corners, {{0, 1, 2}, {0, 2, 3}}}),
              1e-6);
}

TEST(ReadMesh, AsciiPlyCubeOfQuads) {
  ScratchDir dir;
  const TriangleMesh cube = make_unit_cube();
  std::string text =
      "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
      "property float z\nelement face 6\nproperty list uchar int vertex_indices\n"
      "end_header\n";
  for (const Vec3& v : cube.vertices) {
    text +=
        std::to_string(v.x()) + " " + std::to_string(v.y()) + " " + std::to_string(v.z()) + "\n";
  }
  // The cube's faces as quads, outward.
  text += "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
  write_file(dir / "cube.ply", text);
  const TriangleMesh read = read_mesh(dir / "cube.ply");
  EXPECT_EQ(read.vertices.size(), 8u);
  EXPECT_EQ(read.triangles.size(), 12u);
  const MeshTopology topo = analyze_topology(read);
  EXPECT_TRUE(topo.consistently_oriented);
  EXPECT_EQ(topo.genus, 0);
}

TEST(ReadMesh, ObjQuadsAreTriangulatedAndNegativeIndicesResolved) {
  ScratchDir dir;
  write_file(dir / "q.obj",
             "# quad and a relative-index triangle\no thing\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
             "vn 0 0 1\nf 1//1 2//1 3//1 4//1\nv 0 0 1\nf -5 -4 -1\n");
  const TriangleMesh mesh = read_mesh(dir / "q.obj");
  EXPECT_EQ(mesh.vertices.size(), 5u);
  ASSERT_EQ(mesh.triangles.size(), 3u);
  EXPECT_EQ(mesh.triangles[2], (Triangle{0, 1, 4}));
}

TEST(ReadMesh, ObjWithCrlfLineEnds) {
  ScratchDir dir;
  write_file(dir / "crlf.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n");
  EXPECT_EQ(read_mesh(dir / "crlf.obj").triangles.size(), 1u);
  write_file(dir / "bad.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1\r\nf 1 2 3\r\n");
  EXPECT_NE(read_error(dir / "bad.obj").find("line 3:"), std::string::npos)
      << read_error(dir / "bad.obj");
}

TEST(ReadMesh, DuplicateObjVerticesAreWelded) {
  ScratchDir dir;
  // Two triangles sharing an edge through duplicated vertices (-0 equals 0).
  write_file(dir / "d.obj",
             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nv -0 1 0\nv 1 1 0\nf 1 2 3\nf 4 6 5\n");
  const TriangleMesh mesh = read_mesh(dir / "d.obj");
  EXPECT_EQ(mesh.vertices.size(), 4u);
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.triangles[1], (Triangle{1, 3, 2}));
  EXPECT_EQ(analyze_topology(mesh).num_edges, 5u);
}

// ---- bad input: each a single-line Error naming the file ----

void expect_read_error(const fs::path& path, const std::string& fragment) {
  const std::string message = read_error(path);
  EXPECT_FALSE(message.empty()) << path << " was read without error";
  EXPECT_NE(message.find(path.filename().string()), std::string::npos) << message;
  EXPECT_NE(message.find(fragment), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// glTF 2.0 of the unit tetrahedron (outward triangles) under a node translated by +1 along x:
// float positions and uint16 indices in one buffer, which is embedded as a data URI (.gltf) or
// sits in the binary chunk (.glb).
struct GltfTetrahedron {
  std::string buffer;
  std::string json(const std::string& buffer_uri) const {
    const std::string uri = buffer_uri.empty() ? "" : R"(, "uri": ")" + buffer_uri + "\"";
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
 "nodes": [{"mesh": 0, "translation": [1, 0, 0]}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
 "buffers": [{"byteLength": 72)" +
           uri + R"(}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48, "target": 34962},
                 {"buffer": 0, "byteOffset": 48, "byteLength": 24, "target": 34963}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 1]},
               {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}]})";
  }
  GltfTetrahedron() {
    const float positions[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const std::uint16_t indices[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    buffer.append(reinterpret_cast<const char*>(positions), sizeof positions);
    buffer.append(reinterpret_cast<const char*>(indices), sizeof indices);
  }
};

std::string base64(const std::string& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t n = static_cast<std::uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= static_cast<std::uint8_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) n |= static_cast<std::uint8_t>(bytes[i + 2]);
    const std::size_t available = std::min<std::size_t>(3, bytes.size() - i);
    for (std::size_t k = 0; k < 4; ++k) {
      out += k <= available ? kDigits[(n >> (18 - 6 * k)) & 63] : '=';
    }
  }
  return out;
}

void append_u32(std::string& out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((value >> (8 * i)) & 0xffU);
}

void expect_translated_tetrahedron(const TriangleMesh& mesh) {
  ASSERT_EQ(mesh.vertices.size(), 4u);
  ASSERT_EQ(mesh.triangles.size(), 4u);
  EXPECT_EQ(mesh.vertices[0], Vec3(1, 0, 0));
  EXPECT_EQ(mesh.vertices[3], Vec3(1, 0, 1));
  const MeshTopology t = analyze_topology(mesh);
  EXPECT_TRUE(t.consistently_oriented);
  EXPECT_EQ(t.genus, 0);
}

TEST(ReadMesh, GltfWithAnEmbeddedBufferAndNodeTransform) {
  ScratchDir dir;
  const GltfTetrahedron tet;
  write_file(dir / "tet.gltf",
             tet.json("data:application/octet-stream;base64," + base64(tet.buffer)));
  expect_translated_tetrahedron(read_mesh(dir / "tet.gltf"));
}

TEST(ReadMesh, BinaryGlb) {
  ScratchDir dir;
  const GltfTetrahedron tet;
  std::string json = tet.json("");
  while (json.size() % 4 != 0) json += ' ';
  std::string glb = "glTF";
  append_u32(glb, 2);
  append_u32(glb, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + tet.buffer.size()));
  append_u32(glb, static_cast<std::uint32_t>(json.size()));
  glb += "JSON" + json;
  append_u32(glb, static_cast<std::uint32_t>(tet.buffer.size()));
  glb += std::string("BIN\0", 4) + tet.buffer;
  write_file(dir / "tet.GLB", glb);
  expect_translated_tetrahedron(read_mesh(dir / "tet.GLB"));
}

TEST(ReadMeshErrors, MissingFile) {
  ScratchDir dir;
  expect_read_error(dir / "absent.obj", "no such file");
}

// OBJ and ASCII STL declare no counts: a (sparse) file over the input cap is refused by its size.
TEST(ReadMeshErrors, FilesOverTheInputCap) {
  ScratchDir dir;
  for (const char* name : {"huge.obj", "huge.stl"}) {
    write_file(dir / name, "");
    fs::resize_file(dir / name, kMaxInputFileBytes + 1);
    expect_read_error(dir / name, "over 1 GiB");
  }
}

// A binary STL whose header declares 10^9 triangles over 100 bytes: refused at once, nothing
// allocated for the declared count.
TEST(ReadMeshErrors, StlDeclaringMoreTrianglesThanItHolds) {
  ScratchDir dir;
  std::string stl(80, '\0');
  append_u32(stl, 1000000000);
  stl += std::string(100, '\0');
  write_file(dir / "huge.stl", stl);
  expect_read_error(dir / "huge.stl", "cannot read");
}

// Found by fuzz_ply_mesh: PLY vertices without a 'z' made assimp fail an assertion and abort.
TEST(ReadMeshErrors, PlyVerticesWithoutCoordinates) {
  expect_read_error(
      graspecmf::testing::fuzz_regression("ply_mesh", "assimp_triangulate_assert.ply"),
      "no scalar x, y and z properties");
}

// An L-shaped hexagon whose fan from the first corner would fold over is refused, not split
// wrongly; the same L from a corner that sees every other one reads as its 4 triangles.
TEST(ReadMeshErrors, PolygonsAFanCannotSplit) {
  ScratchDir dir;
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n";
  write_file(dir / "folded.ply", header + "6 2 3 4 5 0 1\n");
  expect_read_error(dir / "folded.ply", "cannot split");
  write_file(dir / "fan.ply", header + "6 0 1 2 3 4 5\n");
  const TriangleMesh mesh = read_mesh(dir / "fan.ply");
  EXPECT_EQ(mesh.triangles.size(), 4u);
  EXPECT_NEAR(surface_area(mesh), 3.0, 1e-12);
}

// Found by fuzz_ply_mesh: damaged quad data made assimp's triangulation fail an assertion and
// abort; our own split reads it as a mesh or refuses it with one line.
TEST(ReadMeshErrors, DamagedPolygonData) {
  const fs::path file =
      graspecmf::testing::fuzz_regression("ply_mesh", "assimp_triangulate_assert_2.ply");
  try {
    read_mesh(file);
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("cannot read " + file.string(), 0), 0u) << e.what();
  }
}

// Found by fuzz_ply_mesh: a PLY header declaring an element twice made assimp free memory it did
// not own (AddressSanitizer: bad-free in ~Importer); such headers are refused before assimp.
TEST(ReadMeshErrors, PlyElementDeclaredTwice) {
  expect_read_error(
      graspecmf::testing::fuzz_regression("ply_mesh", "assimp_repeated_element_bad_free.ply"),
      "declared twice");
}

// Found by fuzz_ply_mesh: an ascii PLY whose damaged face data made assimp's reader run for
// 15 s; graspecmf's own reader refuses it at once.
TEST(ReadMeshErrors, PlyFaceDataThatDoesNotFitItsHeader) {
  expect_read_error(graspecmf::testing::fuzz_regression("ply_mesh", "assimp_ascii_slow.ply"),
                    "cannot read");
}

// Found by fuzz_ply_mesh in graspecmf's own PLY reader: an element of no properties declaring
// about 10^18 items, which the reader walked through one by one; such an element holds no data.
TEST(ReadMeshErrors, PlyElementWithoutPropertiesIsNoData) {
  expect_read_error(
      graspecmf::testing::fuzz_regression("ply_mesh", "element_without_properties_slow.ply"),
      "cannot read");
  ScratchDir dir;
  write_file(dir / "tri.ply",
             "ply\nformat ascii 1.0\nelement nothing 1000000000000000000\nelement vertex 3\n"
             "property float x\nproperty float y\nproperty float z\nelement face 1\n"
             "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(read_mesh(dir / "tri.ply").triangles.size(), 1U);
}

// Found by fuzz_ply_mesh: a vertical tab before end_header made assimp's PLY reader hang.
TEST(ReadMeshErrors, PlyHeaderWithControlCharacters) {
  expect_read_error(graspecmf::testing::fuzz_regression("ply_mesh", "assimp_vertical_tab_hang.ply"),
                    "the PLY header is not lines of text");
}

TEST(ReadMeshErrors, UnknownExtension) {
  ScratchDir dir;
  write_file(dir / "cube.off", "OFF\n8 12 0\n");
  expect_read_error(dir / "cube.off", "unsupported extension '.off'");
  write_file(dir / "noext", "v 0 0 0\n");
  expect_read_error(dir / "noext", "unsupported extension");
}

TEST(ReadMeshErrors, UnreadableFormat) {
  ScratchDir dir;
  write_file(dir / "text.stl", "this is not an STL file at all\n");
  expect_read_error(dir / "text.stl", "cannot read");
  write_file(dir / "binary.obj", std::string("\x7f"
                                             "ELF\0\0\x01\x02",
                                             8));
  expect_read_error(dir / "binary.obj", "NUL");
  write_file(dir / "short.ply",
             "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
             "property double x\nproperty double y\nproperty double z\n"
             "element face 1\nproperty list uchar uint vertex_indices\n"
             "end_header\n0123456789");
  expect_read_error(dir / "short.ply", "cannot read");
}

TEST(ReadMeshErrors, TruncatedMugObj) {
  ScratchDir dir;
  const std::string bytes = read_file(kMugPath);
  // 30 % and 50 % of the length fall inside vertex lines ("v -84.46… 112.24… 433.84"): the
  // vertices read, but no face does. The other cuts leave an incomplete last statement.
  std::vector<std::size_t> cuts;
  for (const double f : {0.30, 0.50}) {
    cuts.push_back(static_cast<std::size_t>(f * static_cast<double>(bytes.size())));
  }
  const std::size_t v_line = bytes.find("\nv ", bytes.size() / 4);
  cuts.push_back(v_line + 9);  // "v -12.34": fewer than 3 numbers
  cuts.push_back(v_line + 3);  // "v -": not a number
  const std::size_t f_line = bytes.find("\nf ", bytes.size() * 8 / 10);
  cuts.push_back(f_line + 5);               // "f 123": fewer than 3 corners
  cuts.push_back(f_line + 2);               // "f" alone
  cuts.push_back(bytes.rfind("\nf ") + 8);  // "f 1081 1": the last face, two corners
  for (const std::size_t cut : cuts) {
    const fs::path path = dir / ("cut_" + std::to_string(cut) + ".obj");
    write_file(path, bytes.substr(0, cut));
    const std::string message = read_error(path);
    ASSERT_FALSE(message.empty()) << "cut at byte " << cut << " of " << bytes.size();
    EXPECT_NE(message.find(path.filename().string()), std::string::npos) << message;
    EXPECT_TRUE(message.find("truncated") != std::string::npos ||
                message.find("no faces") != std::string::npos)
        << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(ReadMeshErrors, TruncationAtALineEndIsAValidSmallerFile) {
  // 77 % of the mug's length is exactly the start of the line "f 480 488 487": the cut file is a
  // well-formed OBJ with fewer faces, which no reader can tell from an intended open mesh. It
  // reads, and the missing faces show as boundary edges (documented limit of the truncation check).
  ScratchDir dir;
  const std::string bytes = read_file(kMugPath);
  const auto cut = static_cast<std::size_t>(0.77 * static_cast<double>(bytes.size()));
  ASSERT_EQ(bytes[cut - 1], '\n');
  write_file(dir / "cut.obj", bytes.substr(0, cut));
  const TriangleMesh mesh = read_mesh(dir / "cut.obj");
  EXPECT_LT(mesh.triangles.size(), 2334u);
  EXPECT_GT(analyze_topology(mesh).num_boundary_edges, 0u);
}

TEST(ReadMeshErrors, NoCutOfTheMugReadsAsTheClosedMug) {
  // A cut at any byte is reported, or (when it leaves a well-formed last line: at a line end, or
  // inside the last number, "f 12 34 5" from "f 12 34 56") yields a mesh that is visibly open.
  ScratchDir dir;
  const std::string bytes = read_file(kMugPath);
  const fs::path path = dir / "cut.obj";
  int reported = 0, tested = 0;
  for (std::size_t cut = 1; cut + 1 < bytes.size(); cut += 89) {
    write_file(path, bytes.substr(0, cut));
    ++tested;
    try {
      const TriangleMesh mesh = read_mesh(path);
      EXPECT_FALSE(analyze_topology(mesh).watertight) << "cut at byte " << cut;
    } catch (const Error&) {
      ++reported;
    }
  }
  // Every cut in the vertex block (two thirds of the file) and most in the face block are errors.
  EXPECT_GT(reported, tested * 85 / 100) << reported << " of " << tested;
}

TEST(ReadMeshErrors, NonFiniteCoordinate) {
  ScratchDir dir;
  write_file(dir / "nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  expect_read_error(dir / "nan.obj", "non-finite");
  write_file(dir / "inf.obj", "v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n");
  expect_read_error(dir / "inf.obj", "non-finite");
  write_file(dir / "huge.obj", "v 0 0 0\nv 1 1e999 0\nv 0 1 0\nf 1 2 3\n");
  expect_read_error(dir / "huge.obj", "non-finite");
  write_file(dir / "word.obj", "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n");
  expect_read_error(dir / "word.obj", "not a number");
}

TEST(ReadMeshErrors, EmptyObj) {
  ScratchDir dir;
  write_file(dir / "empty.obj", "");
  expect_read_error(dir / "empty.obj", "no faces");
  write_file(dir / "points.obj", "# only vertices\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  expect_read_error(dir / "points.obj", "no faces");
}

TEST(ReadMeshErrors, FaceIndexOutOfRange) {
  ScratchDir dir;
  write_file(dir / "big.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  expect_read_error(dir / "big.obj", "vert");
  write_file(dir / "neg.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -9\n");
  expect_read_error(dir / "neg.obj", "vert");
  write_file(dir / "quad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4 5\n");
  expect_read_error(dir / "quad.obj", "vert");
  write_file(dir / "zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
  expect_read_error(dir / "zero.obj", "line 4");
}

TEST(ReadMeshErrors, FaceWithTwoCorners) {
  ScratchDir dir;
  write_file(dir / "two.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n");
  expect_read_error(dir / "two.obj", "line 5");
}

TEST(WriteMeshErrors, FailedWritesLeaveNoFile) {
  ScratchDir dir;
  const TriangleMesh cube = make_unit_cube();
  // Missing folder.
  EXPECT_THROW(write_mesh(cube, dir / "missing" / "cube.obj"), Error);
  EXPECT_FALSE(fs::exists(dir / "missing"));
  // Unknown extension.
  EXPECT_THROW(write_mesh(cube, dir / "cube.stl"), Error);
  // Invalid mesh: nothing is written.
  TriangleMesh bad = cube;
  bad.vertices[3].y() = std::nan("");
  EXPECT_THROW(write_mesh(bad, dir / "bad.obj"), Error);
  EXPECT_EQ(dir.num_files(), 0u);
  // The target is a folder: the rename fails and the temporary file is removed.
  fs::create_directory(dir / "taken.ply");
  EXPECT_THROW(write_mesh(cube, dir / "taken.ply"), Error);
  EXPECT_EQ(dir.num_files(), 1u);
  EXPECT_TRUE(fs::is_directory(dir / "taken.ply"));
  EXPECT_TRUE(fs::is_empty(dir / "taken.ply"));
}

}  // namespace
}  // namespace graspecmf::geometry
