#include "graspecmf/geometry/decomposition_cache.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/mesh_cache_file.hpp"

namespace graspecmf::geometry {

namespace fs = std::filesystem;

namespace {

// One binary file per decomposition.
//
// Layout (native byte order): the 8-byte magic, u64 part count, then per part u64 vertex count,
// u64 triangle count, 3 doubles per vertex, 3 u32 per triangle; finally the u64 FNV-1a hash of all
// bytes before it.

constexpr CacheMagic kMagic = {'G', 'C', 'V', 'X', 'D', 'E', 'C', '1'};
// Bump when the algorithm's output changes, so that old cache files are no longer found.
constexpr std::uint64_t kAlgorithmVersion = 1;

std::uint64_t cache_key(const TriangleMesh& mesh, const DecompositionOptions& options) {
  Fnv1a hash;
  hash.add(kMagic, sizeof kMagic);
  hash.add_value(kAlgorithmVersion);
  hash_mesh(hash, mesh);
  hash.add_value(options.resolution);
  hash.add_value(options.max_parts);
  hash.add_value(options.concavity);
  hash.add_value(options.planes_per_axis);
  return hash.value();
}

std::string serialize(const std::vector<TriangleMesh>& parts) {
  std::string out(kMagic, sizeof kMagic);
  put_bytes(out, static_cast<std::uint64_t>(parts.size()));
  for (const TriangleMesh& part : parts) put_mesh(out, part);
  return out;
}

// The parts stored in bytes, or nothing if they are not a complete, intact, valid decomposition.
std::optional<std::vector<TriangleMesh>> deserialize(const std::string& bytes) {
  std::optional<CacheReader> in = CacheReader::open(bytes, kMagic);
  std::uint64_t num_parts = 0;
  if (!in || !in->get(num_parts) || num_parts > in->left() / 16) return std::nullopt;
  std::vector<TriangleMesh> parts(num_parts);
  for (TriangleMesh& part : parts) {
    if (!in->get_mesh(part)) return std::nullopt;
    try {
      validate_mesh(part, "cached convex part");
    } catch (const Error&) {
      return std::nullopt;
    }
  }
  if (in->left() != 0) return std::nullopt;
  return parts;
}

}  // namespace

fs::path decomposition_cache_file(const TriangleMesh& mesh, const DecompositionOptions& options,
                                  const fs::path& cache_dir) {
  return cache_file_path(cache_dir, cache_key(mesh, options), "convex");
}

std::vector<TriangleMesh> cached_convex_decomposition(const TriangleMesh& mesh,
                                                      const DecompositionOptions& options,
                                                      const fs::path& cache_dir) {
  const fs::path path = decomposition_cache_file(mesh, options, cache_dir);
  if (const std::optional<std::string> bytes = read_cache_file(path)) {
    if (std::optional<std::vector<TriangleMesh>> parts = deserialize(*bytes)) {
      return std::move(*parts);
    }
  }
  std::vector<TriangleMesh> parts = convex_decomposition(mesh, options);
  write_cache_file(path, serialize(parts));
  return parts;
}

}  // namespace graspecmf::geometry
