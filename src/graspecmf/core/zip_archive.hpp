#pragma once
// ZIP archives held in memory: an integrity check for the container LibTorch writes checkpoints and
// weights in (catching truncation and damage before LibTorch's own reader, which checks neither,
// parses it), and the checked reading and plain writing of NumPy's .npz archives.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace graspecmf {

// Archives whose entries declare more than this many bytes in total are refused unread.
inline constexpr std::size_t kMaxZipContentBytes = std::size_t{1} << 32;  // 4 GiB

// Checks that bytes hold a whole ZIP archive (ZIP64 included) whose every entry lies inside it, has
// the same name in the central directory as in its local header, is marked as a directory only
// when it is an empty one named "…/", is stored or deflated, and matches the size and CRC-32
// recorded for it; returns the number of entries. Throws Error "<what>: <why>", naming the first
// damaged entry.
std::size_t check_zip_archive(std::string_view bytes, const std::string& what);

// One archive member: its name and uncompressed contents.
struct ZipEntry {
  std::string name;
  std::string contents;
};

// The entries of the archive, in central-directory order, after the checks of check_zip_archive
// (same errors); stored and deflated entries are returned uncompressed.
std::vector<ZipEntry> read_zip_archive(std::string_view bytes, const std::string& what);

// The bytes of a ZIP archive holding entries uncompressed (as NumPy's savez writes), with a fixed
// timestamp. Throws Error if an entry or the archive needs ZIP64 (4 GiB or more).
std::string stored_zip_archive(const std::vector<ZipEntry>& entries);

}  // namespace graspecmf
