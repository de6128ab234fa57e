#pragma once
// Watertight conversion: a closed, consistently oriented, outward 2-manifold triangle mesh made
// from any triangle soup (open pieces, holes, duplicate or flipped faces, self-intersections) by
// alpha wrapping (CGAL's alpha_wrap_3, confined to watertight.cpp), with a report of how far the
// result lies from the input. See docs/prepare-mesh.md for the algorithm and measurements.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "graspecmf/geometry/mesh_topology.hpp"
#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

// A length in WatertightOptions: absolute, in the mesh's units (metres for the project's metric
// meshes), or relative, a fraction of the mesh's bounding-box diagonal. A value of 0 asks for the
// option's default rule.
struct WrapLength {
  double value = 0.0;
  bool relative = false;
};

// The default α: 3 mm, clamped to [diagonal / 150, diagonal / 50] of the mesh's bounding box.
inline constexpr double kDefaultAlpha = 0.003;
inline constexpr double kMinAlphaFraction = 1.0 / 150.0;
inline constexpr double kMaxAlphaFraction = 1.0 / 50.0;
// The default offset: α / 30.
inline constexpr double kDefaultOffsetFraction = 1.0 / 30.0;

struct WatertightOptions {
  // α, the radius of the ball that carves the wrap out of the space around the input: openings
  // narrower than about 2α are closed over, concave details smaller than α are bridged, and the
  // run time grows like (size / α)². Default: kDefaultAlpha clamped as above (3 mm for a 10 cm
  // mug).
  WrapLength alpha;
  // How far the wrap stays outside the input surface: the solid gains about area × offset of
  // volume, and a zero-thickness sheet becomes a slab 2 × offset thick. Default: α / 30.
  WrapLength offset;
  // Wrap even an input that is already closed, consistently oriented and outward.
  bool force = false;
  // Area-uniform points per surface (besides every vertex) for the Hausdorff estimate.
  std::size_t distance_samples = 20000;
};

// The absolute α and offset for this mesh (mesh units).
struct WrapLengths {
  double alpha = 0.0;
  double offset = 0.0;
};

// Resolves options.alpha and options.offset against the mesh's bounding box. Throws Error if a
// value is negative or not finite, or the mesh has no triangles.
WrapLengths resolve_wrap_lengths(const TriangleMesh& mesh, const WatertightOptions& options);

// True if the mesh is watertight, consistently oriented and encloses a positive volume: what a
// simulator needs, so make_watertight returns such a mesh unchanged. The mesh must be valid.
bool is_closed_outward(const TriangleMesh& mesh);

// One-sided maximum distances between two surfaces, estimated from every vertex that a triangle
// uses plus `samples` area-uniform points per surface (seeded), each measured to the nearest point
// on the other surface's triangles.
struct SurfaceDistance {
  double a_to_b = 0.0;  // max over points of a of the distance to b
  double b_to_a = 0.0;
  double hausdorff() const { return a_to_b > b_to_a ? a_to_b : b_to_a; }
};
// Estimates the one-sided distances between the surfaces of a and b (a lower bound of the true
// Hausdorff distance, exact at the vertices). Throws Error if either mesh is invalid or has zero
// area.
SurfaceDistance surface_distance(const TriangleMesh& a, const TriangleMesh& b,
                                 std::size_t samples = 20000, std::uint64_t seed = 1);

struct WatertightReport {
  bool wrapped = false;     // the mesh is the input's alpha wrap
  bool reoriented = false;  // the input was closed but inward: every triangle was flipped
  bool from_cache = false;  // the wrap was read from a disk cache (cached_make_watertight)
  double alpha = 0.0;       // the lengths used (mesh units); 0 when not wrapped
  double offset = 0.0;
  SurfaceDistance distance;  // a = input, b = output; zero when not wrapped
  std::size_t vertices_before = 0, triangles_before = 0, vertices_after = 0, triangles_after = 0;
  MeshTopology topology_before, topology_after;
  std::optional<double> volume_before;  // only when the input is closed and consistently oriented
  double volume_after = 0.0;
  double seconds = 0.0;  // wall time of the call
};

struct WatertightResult {
  TriangleMesh mesh;
  WatertightReport report;
};

// A closed, consistently oriented, outward 2-manifold version of the mesh: the mesh itself if
// is_closed_outward (and not options.force), every triangle flipped if it is closed and oriented
// but inward, else its alpha wrap (zero-area triangles ignored). Throws Error if the mesh fails
// validate_mesh (no triangles, non-finite coordinate, bad index), has zero area, the options are
// invalid, or the wrap does not come out closed, oriented and outward.
WatertightResult make_watertight(const TriangleMesh& mesh, const WatertightOptions& options = {});

// Fills the report's counts, topologies and volumes from the input and the result.
void describe_meshes(const TriangleMesh& input, const TriangleMesh& output,
                     WatertightReport& report);

// The implementation that make_watertight wraps with, e.g. "CGAL 5.5.1 alpha_wrap_3" (reports,
// cache keys).
std::string watertight_backend();

}  // namespace graspecmf::geometry
