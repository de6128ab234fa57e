#include "graspecmf/geometry/watertight_cache.hpp"

#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <system_error>
#include <utility>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/user_cache.hpp"
#include "graspecmf/geometry/mesh_cache_file.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"

namespace graspecmf::geometry {

namespace fs = std::filesystem;

namespace {

// One binary file per wrap.
//
// Layout (native byte order): the 8-byte magic, u64 vertex count, u64 triangle count, 3 doubles
// per vertex, 3 u32 per triangle, then 4 doubles: α, offset, distance input → wrap, distance
// wrap → input; finally the u64 FNV-1a hash of all bytes before it.

constexpr CacheMagic kMagic = {'G', 'W', 'R', 'A', 'P', 'M', 'S', '1'};
// Bump when the output for the same input and options changes, so that old files are not found.
constexpr std::uint64_t kAlgorithmVersion = 1;

struct CachedWrap {
  TriangleMesh mesh;
  double alpha = 0.0, offset = 0.0;
  SurfaceDistance distance;
};

std::uint64_t cache_key(const TriangleMesh& mesh, const WrapLengths& lengths,
                        std::size_t distance_samples) {
  Fnv1a hash;
  hash.add(kMagic, sizeof kMagic);
  hash.add_value(kAlgorithmVersion);
  const std::string backend = watertight_backend();
  hash.add(backend.data(), backend.size());
  hash_mesh(hash, mesh);
  hash.add_value(lengths.alpha);
  hash.add_value(lengths.offset);
  hash.add_value(static_cast<std::uint64_t>(distance_samples));
  return hash.value();
}

std::string serialize(const CachedWrap& wrap) {
  std::string out(kMagic, sizeof kMagic);
  put_mesh(out, wrap.mesh);
  put_bytes(out, wrap.alpha);
  put_bytes(out, wrap.offset);
  put_bytes(out, wrap.distance.a_to_b);
  put_bytes(out, wrap.distance.b_to_a);
  return out;
}

// The wrap stored in bytes, or nothing unless it is complete, intact, and closed and outward.
std::optional<CachedWrap> deserialize(const std::string& bytes) {
  std::optional<CacheReader> in = CacheReader::open(bytes, kMagic);
  CachedWrap wrap;
  if (!in || !in->get_mesh(wrap.mesh) || !in->get(wrap.alpha) || !in->get(wrap.offset) ||
      !in->get(wrap.distance.a_to_b) || !in->get(wrap.distance.b_to_a) || in->left() != 0) {
    return std::nullopt;
  }
  try {
    validate_mesh(wrap.mesh, "cached watertight mesh");
  } catch (const Error&) {
    return std::nullopt;
  }
  if (!is_closed_outward(wrap.mesh)) return std::nullopt;
  return wrap;
}

// A length in metres as millimetres with up to 3 significant digits.
std::string mm(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g mm", 1000.0 * metres);
  return text;
}

}  // namespace

fs::path default_watertight_cache() {
  return user_cache_dir("watertight");
}

fs::path watertight_cache_file(const TriangleMesh& mesh, const WatertightOptions& options,
                               const fs::path& cache_dir) {
  const WrapLengths lengths = resolve_wrap_lengths(mesh, options);
  return cache_file_path(cache_dir, cache_key(mesh, lengths, options.distance_samples), "wrap");
}

WatertightResult cached_make_watertight(const TriangleMesh& mesh, const WatertightOptions& options,
                                        const fs::path& cache_dir) {
  const auto start = std::chrono::steady_clock::now();
  validate_mesh(mesh, "cannot make the mesh watertight");
  // A closed, consistently oriented input is returned as it is or flipped: nothing to cache.
  if (!options.force && analyze_topology(mesh).consistently_oriented) {
    return make_watertight(mesh, options);
  }
  const fs::path path = watertight_cache_file(mesh, options, cache_dir);
  const std::optional<std::string> bytes = read_cache_file(path);
  if (std::optional<CachedWrap> cached = bytes ? deserialize(*bytes) : std::nullopt) {
    WatertightResult result;
    result.mesh = std::move(cached->mesh);
    WatertightReport& report = result.report;
    report.wrapped = true;
    report.from_cache = true;
    report.alpha = cached->alpha;
    report.offset = cached->offset;
    report.distance = cached->distance;
    describe_meshes(mesh, result.mesh, report);
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }
  WatertightResult result = make_watertight(mesh, options);
  if (result.report.wrapped) {
    write_cache_file(path, serialize({result.mesh, result.report.alpha, result.report.offset,
                                      result.report.distance}));
  }
  return result;
}

ClosedMesh closed_mesh_for_simulation(const TriangleMesh& mesh, const std::string& what,
                                      const ClosedMeshOptions& options) {
  ClosedMesh closed;
  if (!options.repair) {
    require_watertight(mesh, what);
    closed.mesh = mesh;
    describe_meshes(mesh, mesh, closed.report);
    return closed;
  }
  validate_mesh(mesh, what);
  if (is_closed_outward(mesh)) {
    closed.mesh = mesh;
    describe_meshes(mesh, mesh, closed.report);
    return closed;
  }
  WatertightOptions wrap = options.wrap;
  wrap.force = false;
  WatertightResult result;
  try {
    result = cached_make_watertight(
        mesh, wrap, options.cache_dir.empty() ? default_watertight_cache() : options.cache_dir);
  } catch (const Error& e) {
    throw Error(what + ": " + e.what());
  }
  closed.mesh = std::move(result.mesh);
  closed.report = result.report;
  closed.repaired = true;
  return closed;
}

std::string repair_summary(const WatertightReport& r) {
  if (r.reoriented) return "every triangle flipped";
  if (!r.wrapped) return {};
  return "alpha wrap (alpha " + mm(r.alpha) + ", offset " + mm(r.offset) + "; Hausdorff distance " +
         mm(r.distance.hausdorff()) + "; genus " + std::to_string(r.topology_after.genus) + ")";
}

std::string repair_note(const std::string& what, const WatertightReport& r) {
  if (r.reoriented) return what + " is closed but faces inwards: every triangle flipped";
  if (!r.wrapped) return {};
  const MeshTopology& t = r.topology_before;
  char problem[160];
  if (t.watertight) {
    std::snprintf(problem, sizeof problem, "is not consistently oriented (%zu misoriented edges)",
                  t.num_misoriented_edges);
  } else {
    std::snprintf(problem, sizeof problem,
                  "is not watertight (%zu boundary, %zu non-manifold, %zu misoriented edges)",
                  t.num_boundary_edges, t.num_nonmanifold_edges, t.num_misoriented_edges);
  }
  if (t.consistently_oriented) {
    std::snprintf(problem, sizeof problem, "is closed but was wrapped (on request, or no volume)");
  }
  return what + " " + problem + ": using its " + repair_summary(r);
}

}  // namespace graspecmf::geometry
