#pragma once
// 64-bit FNV-1a, the content hash of the on-disk caches (file names and trailing checksums).

#include <cstddef>
#include <cstdint>

namespace graspecmf {

// Incremental 64-bit FNV-1a over bytes: the same bytes in the same order give the same value on
// every platform with the same byte order.
class Fnv1a {
 public:
  // Adds size bytes starting at data.
  void add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash_ = (hash_ ^ bytes[i]) * 1099511628211ULL;
  }
  // Adds the object representation of a trivially copyable value.
  template <typename T>
  void add_value(const T& value) {
    add(&value, sizeof value);
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ULL;
};

}  // namespace graspecmf
