#pragma once
// Meshes shared by the geometry tests: boxes, a torus, the bundled ACRONYM mesh paths, and a
// ray–triangle intersection for parity counts.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"
#include "test_support.hpp"

namespace graspecmf::geometry::testing {

namespace fs = std::filesystem;

using graspecmf::testing::read_file;
using graspecmf::testing::ScratchDir;
using graspecmf::testing::write_file;
inline const fs::path kMugPath = graspecmf::testing::sample_mesh_file();
inline const fs::path kGripperPath = graspecmf::testing::gripper_mesh_file();
// /object/scale of the mug's grasp file (also in its file name).
inline constexpr double kMugScale = 0.0002682457830986903;

// Axis-aligned box, 8 vertices (index = x + 2y + 4z bits) and 12 outward triangles.
inline TriangleMesh make_box(const Vec3& lo, const Vec3& hi) {
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.emplace_back((i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(),
                               (i & 4) ? hi.z() : lo.z());
  }
  mesh.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return mesh;
}

inline TriangleMesh make_unit_cube() {
  return make_box(Vec3::Zero(), Vec3::Ones());
}

// Torus around z with major radius R and tube radius r, nu × nv quads split into outward
// triangles.
inline TriangleMesh make_torus(double R, double r, int nu, int nv) {
  TriangleMesh mesh;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const double u = 2.0 * M_PI * i / nu;
      const double v = 2.0 * M_PI * j / nv;
      mesh.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u),
                                 (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  }
  const auto id = [&](int i, int j) {
    return static_cast<std::uint32_t>(((i % nu) * nv) + (j % nv));
  };
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return mesh;
}

// The same mesh with every triangle's orientation reversed.
inline TriangleMesh inverted(TriangleMesh mesh) {
  for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

// Vertices and triangles of b appended to a.
inline TriangleMesh merged(const TriangleMesh& a, const TriangleMesh& b) {
  TriangleMesh out = a;
  const auto offset = static_cast<std::uint32_t>(a.vertices.size());
  out.vertices.insert(out.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (Triangle t : b.triangles) {
    for (std::uint32_t& v : t) v += offset;
    out.triangles.push_back(t);
  }
  return out;
}

// Ray parameter t > 0 where origin + t dir crosses triangle t (Möller–Trumbore), if it does.
inline std::optional<double> ray_hit(const TriangleMesh& mesh, std::size_t t, const Vec3& origin,
                                     const Vec3& dir) {
  const Vec3& a = mesh.vertices[mesh.triangles[t][0]];
  const Vec3 e1 = mesh.vertices[mesh.triangles[t][1]] - a;
  const Vec3 e2 = mesh.vertices[mesh.triangles[t][2]] - a;
  const Vec3 p = dir.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-300) return std::nullopt;
  const Vec3 s = origin - a;
  const double u = s.dot(p) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const Vec3 q = s.cross(e1);
  const double v = dir.dot(q) / det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double hit = e2.dot(q) / det;
  if (hit <= 0.0) return std::nullopt;
  return hit;
}

// Sorted ray parameters at which the ray from origin along dir crosses the mesh.
inline std::vector<double> ray_hits(const TriangleMesh& mesh, const Vec3& origin, const Vec3& dir) {
  std::vector<double> hits;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (const auto hit = ray_hit(mesh, t, origin, dir)) hits.push_back(*hit);
  }
  std::sort(hits.begin(), hits.end());
  return hits;
}

// Number of triangles the ray from origin along dir crosses.
inline int ray_crossings(const TriangleMesh& mesh, const Vec3& origin, const Vec3& dir) {
  return static_cast<int>(ray_hits(mesh, origin, dir).size());
}

}  // namespace graspecmf::geometry::testing
