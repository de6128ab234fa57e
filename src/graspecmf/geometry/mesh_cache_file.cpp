#include "graspecmf/geometry/mesh_cache_file.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <system_error>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"

namespace graspecmf::geometry {

namespace fs = std::filesystem;

namespace {
constexpr std::size_t kVertexBytes = 3 * sizeof(double);
constexpr std::size_t kHashBytes = sizeof(std::uint64_t);
}  // namespace

void hash_mesh(Fnv1a& hash, const TriangleMesh& mesh) {
  hash.add_value(static_cast<std::uint64_t>(mesh.vertices.size()));
  for (const Vec3& v : mesh.vertices) hash.add(v.data(), kVertexBytes);
  hash.add_value(static_cast<std::uint64_t>(mesh.triangles.size()));
  for (const Triangle& t : mesh.triangles) hash.add(t.data(), sizeof t);
}

void put_mesh(std::string& out, const TriangleMesh& mesh) {
  put_bytes(out, static_cast<std::uint64_t>(mesh.vertices.size()));
  put_bytes(out, static_cast<std::uint64_t>(mesh.triangles.size()));
  for (const Vec3& v : mesh.vertices)
    out.append(reinterpret_cast<const char*>(v.data()), kVertexBytes);
  for (const Triangle& t : mesh.triangles) put_bytes(out, t);
}

std::optional<CacheReader> CacheReader::open(const std::string& bytes, const CacheMagic& magic) {
  if (bytes.size() < sizeof magic + kHashBytes ||
      std::memcmp(bytes.data(), magic, sizeof magic) != 0) {
    return std::nullopt;
  }
  const std::size_t payload_end = bytes.size() - kHashBytes;
  Fnv1a hash;
  hash.add(bytes.data(), payload_end);
  std::uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + payload_end, kHashBytes);
  if (stored != hash.value()) return std::nullopt;
  return CacheReader(bytes, sizeof magic, payload_end);
}

bool CacheReader::get_mesh(TriangleMesh& mesh) {
  std::uint64_t num_vertices = 0, num_triangles = 0;
  if (!get(num_vertices) || !get(num_triangles) || num_vertices > left() / kVertexBytes ||
      num_triangles > left() / sizeof(Triangle)) {
    return false;
  }
  mesh.vertices.resize(num_vertices);
  mesh.triangles.resize(num_triangles);
  for (Vec3& v : mesh.vertices) {
    if (!get(v.x()) || !get(v.y()) || !get(v.z())) return false;
  }
  for (Triangle& t : mesh.triangles) {
    if (!get(t)) return false;
  }
  return true;
}

fs::path cache_file_path(const fs::path& cache_dir, std::uint64_t key,
                         const std::string& extension) {
  char name[24];
  std::snprintf(name, sizeof name, "%016llx.", static_cast<unsigned long long>(key));
  return cache_dir / (name + extension);
}

std::optional<std::string> read_cache_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return std::nullopt;
  return bytes;
}

void write_cache_file(const fs::path& path, std::string bytes) {
  const fs::path folder = path.parent_path();
  std::error_code ec;
  if (!folder.empty() && !fs::create_directories(folder, ec) && ec) {
    throw Error("cannot create cache folder " + folder.string() + ": " + ec.message());
  }
  Fnv1a hash;
  hash.add(bytes.data(), bytes.size());
  put_bytes(bytes, hash.value());
  write_file_atomically(path, bytes);
}

}  // namespace graspecmf::geometry
