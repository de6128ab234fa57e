#pragma once
// Integrity check of a ZIP archive held in memory, the container LibTorch writes checkpoints and
// weights in: catches truncation and damage before LibTorch's own reader (which checks neither)
// parses the archive.

#include <cstddef>
#include <string>
#include <string_view>

namespace graspecmf {

// Archives whose entries declare more than this many bytes in total are refused unread.
inline constexpr std::size_t kMaxZipContentBytes = std::size_t{1} << 32;  // 4 GiB

// Checks that bytes hold a whole ZIP archive (ZIP64 included) whose every entry lies inside it, has
// the same name in the central directory as in its local header, is marked as a directory only
// when it is an empty one named "…/", is stored or deflated, and matches the size and CRC-32
// recorded for it; returns the number of entries. Throws Error "<what>: <why>", naming the first
// damaged entry.
std::size_t check_zip_archive(std::string_view bytes, const std::string& what);

}  // namespace graspecmf
