#include "graspecmf/geometry/triangle_mesh.hpp"

#include <cmath>

#include "graspecmf/core/error.hpp"

namespace graspecmf::geometry {

void validate_mesh(const TriangleMesh& mesh, const std::string& what) {
  if (mesh.triangles.empty()) throw Error(what + ": mesh has no triangles");
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!mesh.vertices[i].allFinite()) {
      throw Error(what + ": vertex " + std::to_string(i) + " has a non-finite coordinate");
    }
  }
  const std::size_t n = mesh.vertices.size();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (const std::uint32_t v : tri) {
      if (v >= n) {
        throw Error(what + ": triangle " + std::to_string(t) + " refers to vertex " +
                    std::to_string(v) + " but the mesh has " + std::to_string(n) + " vertices");
      }
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) {
      throw Error(what + ": triangle " + std::to_string(t) + " repeats a vertex index");
    }
  }
}

BoundingBox bounding_box(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) throw Error("bounding_box: mesh has no triangles");
  const Vec3& first = mesh.vertices.at(mesh.triangles.front()[0]);
  BoundingBox box{first, first};
  for (const Triangle& tri : mesh.triangles) {
    for (const std::uint32_t v : tri) {
      const Vec3& x = mesh.vertices.at(v);
      box.min = box.min.cwiseMin(x);
      box.max = box.max.cwiseMax(x);
    }
  }
  return box;
}

double triangle_area(const TriangleMesh& mesh, std::size_t t) {
  const Triangle& tri = mesh.triangles[t];
  const Vec3& a = mesh.vertices[tri[0]];
  return 0.5 * (mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a).norm();
}

Vec3 triangle_normal(const TriangleMesh& mesh, std::size_t t) {
  const Triangle& tri = mesh.triangles[t];
  const Vec3& a = mesh.vertices[tri[0]];
  const Vec3 n = (mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a);
  const double length = n.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return Vec3::Zero();
  return n / length;
}

double surface_area(const TriangleMesh& mesh) {
  double total = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) total += triangle_area(mesh, t);
  return total;
}

TriangleMesh scaled(const TriangleMesh& mesh, double factor) {
  TriangleMesh out = mesh;
  for (Vec3& v : out.vertices) v *= factor;
  return out;
}

TriangleMesh transformed(const TriangleMesh& mesh, const lie::Pose& pose) {
  TriangleMesh out = mesh;
  for (Vec3& v : out.vertices) v = pose.R * v + pose.p;
  return out;
}

TriangleMesh quantized(const TriangleMesh& mesh, double grid) {
  TriangleMesh out = mesh;
  for (Vec3& v : out.vertices) v = lie::rounded(v, grid);
  return out;
}

}  // namespace graspecmf::geometry
