#pragma once
// Mesh files: OBJ (tinyobjloader), PLY (graspecmf's reader), STL binary/ASCII and glTF 2.0
// (.glb/.gltf) (assimp) in; OBJ and PLY out.
// Read meshes are welded (vertices at identical positions merged) and validated.

#include <filesystem>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

// Reads .obj, .stl, .ply, .glb or .gltf (case-insensitive extension); polygons are triangulated and
// vertices at identical positions merged. Throws Error (one line naming the file) if the file is
// missing, unreadable, truncated, or fails validate_mesh.
//
// OBJ: tinyobjloader parses the statements (faces, polygons, negative indices; every group and
// object, `g` and `o`, into the one mesh) and the vertices keep their file order. Every line is
// also checked, because tinyobjloader silently reads "nan", "inf", "1e" or a word as 0 and drops
// faces it cannot use: a `v` needs 3 to 7 numbers, each token a whole number (read correctly
// rounded with std::from_chars, which also supplies the coordinates: tinyobjloader's own parser is
// off in the last bits, which would break round trips) with finite x, y, z; an `f` needs at least 3
// corners of the form v, v/vt, v//vn or v/vt/vn with non-zero integers; every face must yield its
// triangles with in-range vertex indices.
//
// Truncation (a file cut at an arbitrary byte): the cut leaves a last line without a newline, or
// none at all. Such a last line must be a complete statement: a known keyword and, for v/vn/vt/f,
// the checks above; otherwise the error says the file is truncated. A file without any face is an
// error too ("no faces"), so every cut inside the vertex block is reported. A cut that leaves a
// well-formed file cannot be told from an intended smaller file and reads without error: exactly
// at a line end, or inside the last number of a line ("f 12 34 5" from "f 12 34 56"). A last line
// without a newline is accepted when complete, as trimesh writes OBJ files that way. For the
// sample mug, every cut in the vertex block and 71 % of the cuts in the face block are reported;
// the others read as an open (not watertight) mesh.
//
// PLY (ascii, binary little- or big-endian): the vertices' scalar x, y, z (any PLY type, read
// exactly) and the faces' vertex_indices (or vertex_index) lists; other elements and properties are
// skipped. The declared elements must fit in the file before anything is allocated, every list must
// fit in the bytes left, and nothing but whitespace may follow the last element.
//
// STL (binary and ASCII) and glTF 2.0 (binary .glb, or .gltf with embedded or external buffers):
// assimp, all meshes of the scene merged with node transforms applied. glTF coordinates are taken
// as they are (metres, +y up by the glTF convention; no axis change). Debian's assimp stores
// positions as float, so STL and glTF coordinates come back rounded to float precision.
//
// For PLY, STL and glTF, faces of fewer than 3 corners (points, lines) are ignored and polygons are
// split as a fan from their first corner; a polygon such a fan cannot split (concave) is refused.
//
// Then, for every format: vertices at bit-identical positions are merged (−0 = +0; the first
// keeps its place, unused vertices are kept), triangles that repeat a vertex afterwards (zero
// area) are dropped, and the result must pass validate_mesh.
TriangleMesh read_mesh(const std::filesystem::path& path);
// Writes .obj (text, %.17g) or .ply (binary little-endian, double x/y/z, uchar/uint face lists) by
// extension, atomically, with full double precision; read_mesh(write_mesh(m)) == m exactly, for
// both formats, for a mesh without duplicate positions. Throws Error
// on another extension or if validate_mesh fails; then, as on any failed write, the target is left
// untouched.
void write_mesh(const TriangleMesh& mesh, const std::filesystem::path& path);

}  // namespace graspecmf::geometry
