#pragma once
// The pieces shared by the on-disk mesh caches (convex decompositions, watertight wraps): content
// keys, a binary layout for meshes, and checksummed files written atomically. A file is the 8-byte
// magic, the cache's own fields, then the u64 FNV-1a hash of all bytes before it (native order).

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>

#include "graspecmf/core/fnv1a.hpp"
#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

using CacheMagic = char[8];

// Adds the mesh's vertex count, vertex bytes, triangle count and triangle bytes to a content key.
void hash_mesh(Fnv1a& hash, const TriangleMesh& mesh);

// Appends the object representation of a trivially copyable value.
template <typename T>
void put_bytes(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}
// Appends u64 vertex count, u64 triangle count, 3 doubles per vertex and 3 u32 per triangle.
void put_mesh(std::string& out, const TriangleMesh& mesh);

// Reads fixed-size values from the payload of a cache file (after its magic); every read fails
// once it would run past the payload's end.
class CacheReader {
 public:
  // The reader of bytes' payload if bytes start with magic and end with their intact hash; else
  // nothing.
  static std::optional<CacheReader> open(const std::string& bytes, const CacheMagic& magic);

  template <typename T>
  bool get(T& value) {
    if (end_ - pos_ < sizeof value) return false;
    std::memcpy(&value, bytes_->data() + pos_, sizeof value);
    pos_ += sizeof value;
    return true;
  }
  // Reads a mesh written by put_mesh (its indices are not checked).
  bool get_mesh(TriangleMesh& mesh);
  std::size_t left() const { return end_ - pos_; }

 private:
  CacheReader(const std::string& bytes, std::size_t begin, std::size_t end)
      : bytes_(&bytes), pos_(begin), end_(end) {}
  const std::string* bytes_;
  std::size_t pos_, end_;
};

// cache_dir / "<key as 16 hex digits>.<extension>".
std::filesystem::path cache_file_path(const std::filesystem::path& cache_dir, std::uint64_t key,
                                      const std::string& extension);
// The whole file, or nothing if it cannot be read.
std::optional<std::string> read_cache_file(const std::filesystem::path& path);
// Writes bytes (starting with the magic) and their hash to path atomically, creating its folder.
// Throws Error if that fails; the target is then left as it was.
void write_cache_file(const std::filesystem::path& path, std::string bytes);

}  // namespace graspecmf::geometry
