#include "graspecmf/geometry/decomposition_cache.hpp"

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/fnv1a.hpp"

namespace graspecmf::geometry {

namespace fs = std::filesystem;

namespace {

// One binary file per decomposition.
//
// Layout (native byte order): the 8-byte magic, u64 part count, then per part u64 vertex count,
// u64 triangle count, 3 doubles per vertex, 3 u32 per triangle; finally the u64 FNV-1a hash of all
// bytes before it.

constexpr char kMagic[8] = {'G', 'C', 'V', 'X', 'D', 'E', 'C', '1'};
constexpr std::size_t kVertexBytes = 3 * sizeof(double);
// Bump when the algorithm's output changes, so that old cache files are no longer found.
constexpr std::uint64_t kAlgorithmVersion = 1;

std::uint64_t cache_key(const TriangleMesh& mesh, const DecompositionOptions& options) {
  Fnv1a hash;
  hash.add(kMagic, sizeof kMagic);
  hash.add_value(kAlgorithmVersion);
  hash.add_value(static_cast<std::uint64_t>(mesh.vertices.size()));
  for (const Vec3& v : mesh.vertices) hash.add(v.data(), kVertexBytes);
  hash.add_value(static_cast<std::uint64_t>(mesh.triangles.size()));
  for (const Triangle& t : mesh.triangles) hash.add(t.data(), sizeof t);
  hash.add_value(options.resolution);
  hash.add_value(options.max_parts);
  hash.add_value(options.concavity);
  hash.add_value(options.planes_per_axis);
  return hash.value();
}

template <typename T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

std::string serialize(const std::vector<TriangleMesh>& parts) {
  std::string out(kMagic, sizeof kMagic);
  put(out, static_cast<std::uint64_t>(parts.size()));
  for (const TriangleMesh& part : parts) {
    put(out, static_cast<std::uint64_t>(part.vertices.size()));
    put(out, static_cast<std::uint64_t>(part.triangles.size()));
    for (const Vec3& v : part.vertices) {
      out.append(reinterpret_cast<const char*>(v.data()), kVertexBytes);
    }
    for (const Triangle& t : part.triangles) put(out, t);
  }
  Fnv1a hash;
  hash.add(out.data(), out.size());
  put(out, hash.value());
  return out;
}

// Reads fixed-size values from a byte string; false once a read would run past the end.
class ByteReader {
 public:
  ByteReader(const std::string& bytes, std::size_t end) : bytes_(bytes), end_(end) {}
  template <typename T>
  bool get(T& value) {
    if (end_ - pos_ < sizeof value) return false;
    std::memcpy(&value, bytes_.data() + pos_, sizeof value);
    pos_ += sizeof value;
    return true;
  }
  std::size_t left() const { return end_ - pos_; }

 private:
  const std::string& bytes_;
  std::size_t end_;
  std::size_t pos_ = 0;
};

bool read_part(ByteReader& in, TriangleMesh& part) {
  std::uint64_t num_vertices = 0;
  std::uint64_t num_triangles = 0;
  if (!in.get(num_vertices) || !in.get(num_triangles)) return false;
  if (num_vertices > in.left() / kVertexBytes || num_triangles > in.left() / sizeof(Triangle)) {
    return false;
  }
  part.vertices.resize(num_vertices);
  part.triangles.resize(num_triangles);
  for (Vec3& v : part.vertices) {
    if (!in.get(v.x()) || !in.get(v.y()) || !in.get(v.z())) return false;
  }
  for (Triangle& t : part.triangles) {
    if (!in.get(t)) return false;
  }
  return true;
}

// The parts stored in bytes, or nothing if they are not a complete, intact, valid decomposition.
std::optional<std::vector<TriangleMesh>> deserialize(const std::string& bytes) {
  constexpr std::size_t kHashSize = sizeof(std::uint64_t);
  if (bytes.size() < sizeof kMagic + kHashSize ||
      std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) {
    return std::nullopt;
  }
  const std::size_t payload = bytes.size() - kHashSize;
  Fnv1a hash;
  hash.add(bytes.data(), payload);
  std::uint64_t stored_hash = 0;
  std::memcpy(&stored_hash, bytes.data() + payload, kHashSize);
  if (stored_hash != hash.value()) return std::nullopt;

  ByteReader in(bytes, payload);
  std::array<char, sizeof kMagic> magic{};
  std::uint64_t num_parts = 0;
  if (!in.get(magic) || !in.get(num_parts) || num_parts > in.left() / 16) return std::nullopt;
  std::vector<TriangleMesh> parts(num_parts);
  for (TriangleMesh& part : parts) {
    if (!read_part(in, part)) return std::nullopt;
    try {
      validate_mesh(part, "cached convex part");
    } catch (const Error&) {
      return std::nullopt;
    }
  }
  if (in.left() != 0) return std::nullopt;
  return parts;
}

std::optional<std::vector<TriangleMesh>> read_cache(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return std::nullopt;
  return deserialize(bytes);
}

void write_cache(const fs::path& path, const std::vector<TriangleMesh>& parts) {
  const fs::path folder = path.parent_path();
  std::error_code ec;
  if (!folder.empty() && !fs::create_directories(folder, ec) && ec) {
    throw Error("cannot create cache folder " + folder.string() + ": " + ec.message());
  }
  const std::string bytes = serialize(parts);
  write_atomically(path, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) throw Error("cannot write " + path.string() + ": write failed");
  });
}

}  // namespace

fs::path decomposition_cache_file(const TriangleMesh& mesh, const DecompositionOptions& options,
                                  const fs::path& cache_dir) {
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.convex",
                static_cast<unsigned long long>(cache_key(mesh, options)));
  return cache_dir / name;
}

std::vector<TriangleMesh> cached_convex_decomposition(const TriangleMesh& mesh,
                                                      const DecompositionOptions& options,
                                                      const fs::path& cache_dir) {
  const fs::path path = decomposition_cache_file(mesh, options, cache_dir);
  if (std::optional<std::vector<TriangleMesh>> parts = read_cache(path)) return std::move(*parts);
  std::vector<TriangleMesh> parts = convex_decomposition(mesh, options);
  write_cache(path, parts);
  return parts;
}

}  // namespace graspecmf::geometry
