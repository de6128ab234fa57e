#include "graspecmf/core/zip_archive.hpp"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>

#include "graspecmf/core/error.hpp"

namespace graspecmf {
namespace {

constexpr std::uint32_t kLocalSignature = 0x04034b50;
constexpr std::uint32_t kCentralSignature = 0x02014b50;
constexpr std::uint32_t kEndSignature = 0x06054b50;
constexpr std::uint32_t kZip64EndSignature = 0x06064b50;
constexpr std::uint32_t kZip64LocatorSignature = 0x07064b50;
constexpr std::size_t kEndSize = 22, kZip64LocatorSize = 20, kZip64EndSize = 56;
constexpr std::size_t kCentralSize = 46, kLocalSize = 30;
constexpr std::uint64_t kMaxComment = 0xffff;
constexpr std::uint32_t kZip64Marker = 0xffffffff;

// The archive's bytes with bounds-checked little-endian reads; every failure names the archive.
class ZipBytes {
 public:
  ZipBytes(std::string_view bytes, const std::string& what) : bytes_(bytes), what_(what) {}

  std::size_t size() const { return bytes_.size(); }

  // The n-byte (n ≤ 8) little-endian unsigned integer at offset; fails past the end.
  std::uint64_t read(std::uint64_t offset, int n) const {
    require_range(offset, static_cast<std::uint64_t>(n), "a header");
    std::uint64_t value = 0;
    for (int i = n - 1; i >= 0; --i) {
      value = (value << 8) | static_cast<unsigned char>(bytes_[offset + static_cast<unsigned>(i)]);
    }
    return value;
  }

  // The bytes [offset, offset + length); fails unless they lie inside the archive.
  std::string_view range(std::uint64_t offset, std::uint64_t length, const char* part) const {
    require_range(offset, length, part);
    return bytes_.substr(offset, length);
  }

  [[noreturn]] void fail(const std::string& why) const {
    throw Error(what_ + ": damaged or not a ZIP archive: " + why);
  }

 private:
  void require_range(std::uint64_t offset, std::uint64_t length, const char* part) const {
    if (offset > bytes_.size() || length > bytes_.size() - offset) {
      fail(std::string(part) + " runs past the end of the file (truncated?)");
    }
  }

  std::string_view bytes_;
  const std::string& what_;
};

// Where the central directory lies and how many entries it holds.
struct Directory {
  std::uint64_t offset = 0;
  std::uint64_t size = 0;
  std::uint64_t entries = 0;
};

// The end-of-central-directory record: the last signature whose comment ends the file.
Directory find_directory(const ZipBytes& zip) {
  if (zip.size() < kEndSize) zip.fail("shorter than an end-of-central-directory record");
  const std::uint64_t last = zip.size() - kEndSize;
  const std::uint64_t first = last > kMaxComment ? last - kMaxComment : 0;
  for (std::uint64_t at = last + 1; at-- > first;) {
    if (zip.read(at, 4) != kEndSignature || at + kEndSize + zip.read(at + 20, 2) != zip.size()) {
      continue;
    }
    Directory dir{zip.read(at + 16, 4), zip.read(at + 12, 4), zip.read(at + 10, 2)};
    std::uint64_t end = at;  // the directory ends where the records after it begin
    if (at >= kZip64LocatorSize && zip.read(at - kZip64LocatorSize, 4) == kZip64LocatorSignature) {
      const std::uint64_t record = zip.read(at - kZip64LocatorSize + 8, 8);
      if (zip.read(record, 4) != kZip64EndSignature || record > at - kZip64LocatorSize ||
          at - kZip64LocatorSize - record < kZip64EndSize) {
        zip.fail("the ZIP64 end-of-central-directory record is misplaced");
      }
      dir = {zip.read(record + 48, 8), zip.read(record + 40, 8), zip.read(record + 32, 8)};
      end = record;
    }
    if (dir.offset > end || dir.size != end - dir.offset) {
      zip.fail("the central directory does not end where its end record begins");
    }
    if (dir.entries > dir.size / kCentralSize) {
      zip.fail("the central directory is too small for the entries it declares");
    }
    return dir;
  }
  zip.fail("no end-of-central-directory record (truncated?)");
}

// One central-directory entry's facts.
struct Entry {
  std::string name;
  std::uint64_t flags = 0, method = 0, crc = 0, compressed = 0, size = 0, local = 0;
  std::uint64_t attributes = 0;  // external file attributes (MS-DOS ones in the low byte)
};

// Replaces the fields that hold the ZIP64 marker by their 64-bit values from the extra field.
void read_zip64_sizes(const ZipBytes& zip, std::uint64_t extra, std::uint64_t extra_end,
                      Entry& entry) {
  std::array<std::uint64_t*, 3> fields{&entry.size, &entry.compressed, &entry.local};
  if (std::none_of(fields.begin(), fields.end(), [](auto* f) { return *f == kZip64Marker; })) {
    return;
  }
  for (std::uint64_t at = extra; at + 4 <= extra_end;) {
    const std::uint64_t id = zip.read(at, 2), length = zip.read(at + 2, 2);
    if (at + 4 + length > extra_end) break;
    if (id == 1) {
      std::uint64_t next = at + 4;
      for (std::uint64_t* field : fields) {
        if (*field != kZip64Marker) continue;
        if (next + 8 > at + 4 + length) zip.fail("entry '" + entry.name + "': short ZIP64 field");
        *field = zip.read(next, 8);
        next += 8;
      }
      return;
    }
    at += 4 + length;
  }
  zip.fail("entry '" + entry.name + "' lacks the ZIP64 sizes its header promises");
}

// The CRC-32 of bytes.
std::uint32_t crc_of(std::string_view bytes) {
  uLong crc = crc32(0L, Z_NULL, 0);
  constexpr std::size_t kChunk = std::size_t{1} << 30;
  for (std::size_t at = 0; at < bytes.size(); at += kChunk) {
    const std::size_t n = std::min(kChunk, bytes.size() - at);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data() + at), static_cast<uInt>(n));
  }
  return static_cast<std::uint32_t>(crc);
}

// Inflates a raw deflate stream; fails unless the stream is whole, uses all of data and inflates
// to exactly the entry's recorded size.
std::string inflated(const ZipBytes& zip, const Entry& entry, std::string_view data) {
  z_stream stream{};
  if (inflateInit2(&stream, -MAX_WBITS) != Z_OK) zip.fail("zlib cannot start inflating");
  std::array<unsigned char, 1 << 16> buffer{};
  std::string out;
  std::size_t consumed = 0;
  int status = Z_OK;
  while (status == Z_OK) {
    const std::size_t n = std::min<std::size_t>(data.size() - consumed, 1 << 30);
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data() + consumed));
    stream.avail_in = static_cast<uInt>(n);
    stream.next_out = buffer.data();
    stream.avail_out = static_cast<uInt>(buffer.size());
    status = inflate(&stream, Z_NO_FLUSH);
    consumed += n - stream.avail_in;
    out.append(reinterpret_cast<const char*>(buffer.data()), buffer.size() - stream.avail_out);
    if (out.size() > entry.size) break;
  }
  inflateEnd(&stream);
  if (status != Z_STREAM_END || out.size() != entry.size || consumed != data.size()) {
    zip.fail("entry '" + entry.name + "' does not inflate to its recorded size");
  }
  return out;
}

// A flag word in hexadecimal.
std::string hex(std::uint64_t value) {
  constexpr const char* kDigits = "0123456789abcdef";
  std::string text;
  do {
    text.insert(text.begin(), kDigits[value & 15]);
    value >>= 4;
  } while (value != 0);
  return text;
}

// Reads the central-directory entry at `at`; returns the offset of the next one.
std::uint64_t read_entry(const ZipBytes& zip, std::uint64_t at, std::uint64_t end, Entry& entry) {
  if (at + kCentralSize > end || zip.read(at, 4) != kCentralSignature) {
    zip.fail("a central-directory entry is missing or misplaced");
  }
  const std::uint64_t name = zip.read(at + 28, 2), extra = zip.read(at + 30, 2);
  const std::uint64_t next = at + kCentralSize + name + extra + zip.read(at + 32, 2);
  if (next > end) zip.fail("a central-directory entry runs past the directory");
  entry.name = std::string(zip.range(at + kCentralSize, name, "an entry name"));
  entry.flags = zip.read(at + 8, 2);
  entry.method = zip.read(at + 10, 2);
  entry.crc = zip.read(at + 16, 4);
  entry.compressed = zip.read(at + 20, 4);
  entry.size = zip.read(at + 24, 4);
  entry.attributes = zip.read(at + 38, 4);
  entry.local = zip.read(at + 42, 4);
  read_zip64_sizes(zip, at + kCentralSize + name, at + kCentralSize + name + extra, entry);
  return next;
}

// Checks one entry's local header, bounds, size and CRC-32; returns its contents.
std::string checked_contents(const ZipBytes& zip, const Entry& entry, const Directory& dir) {
  const std::string quoted = "entry '" + entry.name + "'";
  // Allowed: deflate options (bits 1, 2), a data descriptor (3), UTF-8 names (11). Encryption
  // (0, 6, 13) and patch data (5) make readers refuse the entry, LibTorch's at a point it cannot
  // recover from.
  constexpr std::uint64_t kAllowedFlags = 0x080e;
  if ((entry.flags & ~kAllowedFlags) != 0) {
    zip.fail(quoted + " has unsupported flags 0x" + hex(entry.flags) + " (encryption, patches)");
  }
  // LibTorch's ZIP reader (miniz) reads an entry with the MS-DOS directory attribute as empty; an
  // empty code file then terminated LibTorch's TorchScript importer.
  constexpr std::uint64_t kDosDirectory = 0x10;
  if ((entry.attributes & kDosDirectory) != 0 &&
      (entry.name.empty() || entry.name.back() != '/' || entry.size != 0)) {
    zip.fail(quoted + " is marked as a directory but is a file");
  }
  if (entry.method != 0 && entry.method != 8) {
    zip.fail(quoted + " uses compression method " + std::to_string(entry.method) +
             " (only stored and deflated entries are read)");
  }
  if (entry.local > dir.offset || zip.read(entry.local, 4) != kLocalSignature) {
    zip.fail(quoted + ": its local header is missing or misplaced");
  }
  // Readers find entries by their central-directory names: a damaged name must not pass.
  const std::uint64_t local_name = zip.read(entry.local + 26, 2);
  if (zip.range(entry.local + kLocalSize, local_name, "an entry name") != entry.name) {
    zip.fail(quoted + ": its name differs from its local header's");
  }
  const std::uint64_t data = entry.local + kLocalSize + local_name + zip.read(entry.local + 28, 2);
  if (data > dir.offset || entry.compressed > dir.offset - data) {
    zip.fail(quoted + "'s data runs into the central directory");
  }
  const std::string_view bytes = zip.range(data, entry.compressed, "an entry's data");
  if (entry.method == 0 && entry.compressed != entry.size) {
    zip.fail(quoted + " is stored but its two recorded sizes differ");
  }
  std::string contents = entry.method == 0 ? std::string(bytes) : inflated(zip, entry, bytes);
  if (crc_of(contents) != entry.crc) zip.fail(quoted + " does not match its CRC-32");
  return contents;
}

// Visits every entry of the archive with its checked contents, in central-directory order.
void visit_entries(std::string_view bytes, const std::string& what,
                   const std::function<void(const std::string&, std::string&&)>& visit) {
  const ZipBytes zip(bytes, what);
  const Directory dir = find_directory(zip);
  const std::uint64_t end = dir.offset + dir.size;
  std::uint64_t total = 0;
  Entry entry;
  for (std::uint64_t i = 0, at = dir.offset; i < dir.entries; ++i) {
    at = read_entry(zip, at, end, entry);
    if (entry.size > kMaxZipContentBytes - total) {
      zip.fail("its entries declare more than " + std::to_string(kMaxZipContentBytes >> 30) +
               " GiB");
    }
    total += entry.size;
    visit(entry.name, checked_contents(zip, entry, dir));
  }
}

// Appends the n-byte little-endian value to out.
void put(std::string& out, std::uint64_t value, int n) {
  for (int i = 0; i < n; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
}

}  // namespace

std::size_t check_zip_archive(std::string_view bytes, const std::string& what) {
  std::size_t count = 0;
  visit_entries(bytes, what, [&](const std::string&, std::string&&) { ++count; });
  return count;
}

std::vector<ZipEntry> read_zip_archive(std::string_view bytes, const std::string& what) {
  std::vector<ZipEntry> entries;
  visit_entries(bytes, what, [&](const std::string& name, std::string&& contents) {
    entries.push_back({name, std::move(contents)});
  });
  return entries;
}

std::string stored_zip_archive(const std::vector<ZipEntry>& entries) {
  std::string out, directory;
  for (const ZipEntry& entry : entries) {
    if (entry.contents.size() >= kZip64Marker || out.size() >= kZip64Marker ||
        entry.name.size() > 0xffff) {
      throw Error("ZIP entry '" + entry.name + "' is too large for a plain ZIP archive");
    }
    const std::uint32_t crc = crc_of(entry.contents);
    // The header fields both records share: version, flags, method, time, date, CRC and sizes.
    std::string common;
    put(common, 20, 2);
    put(common, 0, 2);
    put(common, 0, 2);
    put(common, 0, 2);
    put(common, 0x21, 2);  // 1980-01-01: a fixed date keeps the archive reproducible
    put(common, crc, 4);
    put(common, entry.contents.size(), 4);
    put(common, entry.contents.size(), 4);
    put(common, entry.name.size(), 2);
    put(common, 0, 2);
    put(directory, kCentralSignature, 4);
    put(directory, 20, 2);
    directory += common;
    put(directory, 0, 2 + 2 + 2 + 4);  // comment length, disk, internal and external attributes
    put(directory, out.size(), 4);
    directory += entry.name;
    put(out, kLocalSignature, 4);
    out += common;
    out += entry.name;
    out += entry.contents;
  }
  if (out.size() >= kZip64Marker || entries.size() >= 0xffff) {
    throw Error("too much data for a plain ZIP archive");
  }
  const std::size_t directory_offset = out.size();
  out += directory;
  put(out, kEndSignature, 4);
  put(out, 0, 4);  // this disk, the directory's disk
  put(out, entries.size(), 2);
  put(out, entries.size(), 2);
  put(out, directory.size(), 4);
  put(out, directory_offset, 4);
  put(out, 0, 2);  // comment length
  return out;
}

}  // namespace graspecmf
