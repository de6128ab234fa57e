#include "graspecmf/geometry/watertight.hpp"

// CGAL stays in this file: it is compiled on its own with CGAL's flags (-frounding-math), so that
// the rest of the geometry layer keeps its floating-point code generation.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>
#include <CGAL/version.h>
#include <CGAL/version_macros.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/surface_sampling.hpp"
#include "graspecmf/geometry/unsigned_distance.hpp"

namespace graspecmf::geometry {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

Point to_point(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

// Signed volume enclosed by the triangles (positive for an outward closed mesh), from the bounding
// box centre.
double signed_volume(const TriangleMesh& mesh) {
  const Vec3 c = bounding_box(mesh).center();
  double six_v = 0.0;
  for (const Triangle& t : mesh.triangles) {
    six_v +=
        (mesh.vertices[t[0]] - c).dot((mesh.vertices[t[1]] - c).cross(mesh.vertices[t[2]] - c));
  }
  return six_v / 6.0;
}

TriangleMesh flipped(const TriangleMesh& mesh) {
  TriangleMesh out = mesh;
  for (Triangle& t : out.triangles) std::swap(t[1], t[2]);
  return out;
}

double checked_length(const WrapLength& length, double diagonal, const char* name) {
  if (!std::isfinite(length.value) || length.value < 0.0) {
    throw Error(std::string("watertight: ") + name + " must be a positive number (got " +
                std::to_string(length.value) + ")");
  }
  return length.relative ? length.value * diagonal : length.value;
}

// The alpha wrap of the mesh's proper triangles as a TriangleMesh (CGAL numbers its vertices and
// faces consecutively in a fresh Surface_mesh).
TriangleMesh alpha_wrap(const TriangleMesh& mesh, const WrapLengths& lengths) {
  std::vector<Point> points;
  points.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) points.push_back(to_point(v));
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    if (!CGAL::collinear(points[t[0]], points[t[1]], points[t[2]])) {
      faces.push_back({t[0], t[1], t[2]});
    }
  }
  if (faces.empty()) throw Error("watertight: every triangle of the mesh has zero area");
  SurfaceMesh wrap;
  try {
    CGAL::alpha_wrap_3(points, faces, lengths.alpha, lengths.offset, wrap);
  } catch (const std::exception& e) {
    throw Error("watertight: the alpha wrap failed: " + first_line(e.what()));
  }
  wrap.collect_garbage();
  TriangleMesh out;
  out.vertices.reserve(wrap.number_of_vertices());
  for (const SurfaceMesh::Vertex_index v : wrap.vertices()) {
    const Point& p = wrap.point(v);
    out.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  out.triangles.reserve(wrap.number_of_faces());
  for (const SurfaceMesh::Face_index f : wrap.faces()) {
    Triangle tri{};
    std::size_t k = 0;
    for (const SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(wrap.halfedge(f), wrap)) {
      if (k == 3) throw Error("watertight: the alpha wrap has a face that is not a triangle");
      tri[k++] = static_cast<std::uint32_t>(static_cast<std::size_t>(v));
    }
    if (k != 3) throw Error("watertight: the alpha wrap has a face that is not a triangle");
    out.triangles.push_back(tri);
  }
  return out;
}

// Largest distance from the points to a surface.
double max_distance(const std::vector<Vec3>& points, const UnsignedDistance& surface) {
  double worst = 0.0;
  for (const Vec3& p : points) worst = std::max(worst, surface(p));
  return worst;
}

// Every vertex a triangle uses, then `samples` area-uniform surface points.
std::vector<Vec3> probe_points(const TriangleMesh& mesh, std::size_t samples, std::uint64_t seed) {
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const Triangle& t : mesh.triangles) {
    for (const std::uint32_t v : t) used[v] = 1;
  }
  std::vector<Vec3> points;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (used[v]) points.push_back(mesh.vertices[v]);
  }
  std::vector<Vec3> surface = sample_surface(mesh, samples, seed).points;
  points.insert(points.end(), surface.begin(), surface.end());
  return points;
}

}  // namespace

WrapLengths resolve_wrap_lengths(const TriangleMesh& mesh, const WatertightOptions& options) {
  const double diagonal = bounding_box(mesh).extent().norm();
  WrapLengths lengths;
  lengths.alpha = checked_length(options.alpha, diagonal, "alpha");
  if (lengths.alpha == 0.0) {
    lengths.alpha =
        std::clamp(kDefaultAlpha, kMinAlphaFraction * diagonal, kMaxAlphaFraction * diagonal);
  }
  lengths.offset = checked_length(options.offset, diagonal, "offset");
  if (lengths.offset == 0.0) lengths.offset = kDefaultOffsetFraction * lengths.alpha;
  if (!(lengths.alpha > 0.0) || !(lengths.offset > 0.0) || !std::isfinite(lengths.alpha) ||
      !std::isfinite(lengths.offset)) {
    throw Error("watertight: alpha and offset must be positive (the mesh has no extent?)");
  }
  return lengths;
}

bool is_closed_outward(const TriangleMesh& mesh) {
  return analyze_topology(mesh).consistently_oriented && signed_volume(mesh) > 0.0;
}

SurfaceDistance surface_distance(const TriangleMesh& a, const TriangleMesh& b, std::size_t samples,
                                 std::uint64_t seed) {
  const UnsignedDistance to_a(a), to_b(b);
  SurfaceDistance d;
  d.a_to_b = max_distance(probe_points(a, samples, seed), to_b);
  d.b_to_a = max_distance(probe_points(b, samples, seed + 1), to_a);
  return d;
}

void describe_meshes(const TriangleMesh& input, const TriangleMesh& output,
                     WatertightReport& report) {
  report.vertices_before = input.vertices.size();
  report.triangles_before = input.triangles.size();
  report.vertices_after = output.vertices.size();
  report.triangles_after = output.triangles.size();
  report.topology_before = analyze_topology(input);
  report.topology_after = analyze_topology(output);
  report.volume_before.reset();
  if (report.topology_before.consistently_oriented) report.volume_before = signed_volume(input);
  report.volume_after = signed_volume(output);
}

WatertightResult make_watertight(const TriangleMesh& mesh, const WatertightOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  validate_mesh(mesh, "cannot make the mesh watertight");
  const WrapLengths lengths = resolve_wrap_lengths(mesh, options);
  WatertightResult result;
  WatertightReport& report = result.report;
  const bool oriented = analyze_topology(mesh).consistently_oriented;
  const double volume = oriented ? signed_volume(mesh) : 0.0;
  if (!options.force && oriented && volume > 0.0) {
    result.mesh = mesh;
  } else if (!options.force && oriented && volume < 0.0) {
    result.mesh = flipped(mesh);
    report.reoriented = true;
  } else {
    result.mesh = alpha_wrap(mesh, lengths);
    const MeshTopology topology = analyze_topology(result.mesh);
    if (!topology.consistently_oriented) {
      throw Error("watertight: the alpha wrap is not a closed, consistently oriented surface");
    }
    if (signed_volume(result.mesh) < 0.0) result.mesh = flipped(result.mesh);
    if (!(signed_volume(result.mesh) > 0.0)) {
      throw Error("watertight: the alpha wrap encloses no volume");
    }
    report.wrapped = true;
    report.alpha = lengths.alpha;
    report.offset = lengths.offset;
    report.distance = surface_distance(mesh, result.mesh, options.distance_samples);
  }
  describe_meshes(mesh, result.mesh, report);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::string watertight_backend() {
  return std::string("CGAL ") + CGAL_VERSION_STR + " alpha_wrap_3";
}

}  // namespace graspecmf::geometry
