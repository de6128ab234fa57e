#include "graspecmf/core/zip_archive.hpp"

#include <gtest/gtest.h>

#include <string>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/input_file.hpp"
#include "test_support.hpp"

namespace graspecmf {
namespace {

using testing::bundled_weights_file;
using testing::expect_error;

// The bundled weights file's bytes.
const std::string& weights() {
  static const std::string bytes = read_input_file(bundled_weights_file());
  return bytes;
}

// The offset of the data of the entry named `name` (found through its local header).
std::size_t entry_data(const std::string& bytes, const std::string& name) {
  const std::size_t at = bytes.find(name);  // local headers come before the central directory
  EXPECT_NE(at, std::string::npos) << name;
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
  const std::size_t extra = byte(at - 2) | (byte(at - 1) << 8);
  return at + name.size() + extra;
}

// The central-directory entry of `name` (the name's last occurrence), less its 46-byte header.
std::size_t central_entry(const std::string& bytes, const std::string& name) {
  return bytes.rfind(name) - 46;
}

// Expects check_zip_archive to refuse bytes with a message containing fragment.
void expect_refused(const std::string& bytes, const std::string& fragment) {
  expect_error([&] { check_zip_archive(bytes, "model.pt"); }, "model.pt: damaged or not a ZIP");
  expect_error([&] { check_zip_archive(bytes, "model.pt"); }, fragment);
}

TEST(ZipArchive, AcceptsTheBundledWeightsAndCountsTheirEntries) {
  // Python's zipfile lists 100 entries: 25 tensors, 72 TorchScript code and debug files (3 of
  // them deflated), data.pkl, constants.pkl and version.
  EXPECT_EQ(check_zip_archive(weights(), "model.pt"), 100U);
}

TEST(ZipArchive, AcceptsArchivesWrittenByPythonsZipfile) {
  // fuzz/corpus/zip/: stored and deflated entries, a ZIP64 local header, an archive comment and
  // an empty archive.
  const std::pair<const char*, std::size_t> seeds[] = {{"stored.zip", 2},
                                                       {"deflated.zip", 2},
                                                       {"zip64.zip", 1},
                                                       {"comment.zip", 1},
                                                       {"empty_archive.zip", 0}};
  for (const auto& [name, entries] : seeds) {
    EXPECT_EQ(check_zip_archive(read_input_file(testing::fuzz_seed("zip", name)), name), entries)
        << name;
  }
}

TEST(ZipArchive, EveryTruncationIsRefused) {
  const std::string& bytes = weights();
  for (std::size_t keep = 0; keep < bytes.size(); keep += 4099) {
    expect_refused(bytes.substr(0, keep), "");
  }
  expect_refused(bytes.substr(0, bytes.size() - 1), "no end-of-central-directory record");
}

TEST(ZipArchive, AFlippedBitInAStoredTensorIsRefused) {
  std::string bytes = weights();
  bytes[entry_data(bytes, "archive/data/10") + 2000] ^= 0x80;  // one float's sign bit
  expect_refused(bytes, "entry 'archive/data/10' does not match its CRC-32");
}

TEST(ZipArchive, DamagedDeflatedCodeIsRefused) {
  std::string bytes = weights();
  bytes[entry_data(bytes, "archive/code/__torch__.py") + 3] ^= 0x01;
  expect_refused(bytes, "entry 'archive/code/__torch__.py'");
}

TEST(ZipArchive, DamagedCentralDirectoryIsRefused) {
  std::string crc = weights();
  crc[central_entry(crc, "archive/data.pkl") + 16] ^= 0x01;  // its recorded CRC-32
  expect_refused(crc, "entry 'archive/data.pkl' does not match its CRC-32");

  std::string method = weights();
  method[central_entry(method, "archive/data.pkl") + 10] = 12;  // bzip2
  expect_refused(method, "compression method 12");

  std::string flags = weights();
  flags[central_entry(flags, "archive/data.pkl") + 8] |= 0x40;  // strong encryption
  expect_refused(flags, "entry 'archive/data.pkl' has unsupported flags 0x");

  std::string name = weights();
  name[central_entry(name, "archive/data.pkl") + 46 + 14] = 'q';  // archive/data.pkl → data.pql
  expect_refused(name, "its name differs from its local header's");

  std::string directory = weights();
  directory[central_entry(directory, "archive/data.pkl") + 38] = 0x10;  // MS-DOS directory
  expect_refused(directory, "entry 'archive/data.pkl' is marked as a directory but is a file");

  std::string offset = weights();
  offset[central_entry(offset, "archive/data.pkl") + 45] = 0x7f;  // local header far past the end
  expect_refused(offset, "local header is missing or misplaced");
}

// fuzz_checkpoint's first finding: a checkpoint whose central directory names one code file
// differently from its local header passed the CRC checks, and LibTorch's TorchScript importer
// then terminated the process (an exception through a noexcept frame while parsing a type).
TEST(FuzzRegressions, CheckpointWithARenamedCodeFile) {
  const std::string bytes = read_input_file(
      testing::fuzz_regression("checkpoint", "central_name_differs_libtorch_terminate.pt"));
  expect_refused(bytes, "its name differs from its local header's");
}

// Its second: a central-directory entry of a code file with unsupported flag bits (0x08da) passed,
// LibTorch's ZIP reader refused the entry, and the importer terminated the process again. (An
// earlier entry of the same input is also marked as a directory, which is now refused first.)
TEST(FuzzRegressions, CheckpointWithUnsupportedEntryFlags) {
  const std::string bytes =
      read_input_file(testing::fuzz_regression("checkpoint", "entry_flags_libtorch_terminate.pt"));
  expect_refused(bytes,
                 "entry 'archive/code/__torch__/___torch_mangle_7.py' is marked as a "
                 "directory but is a file");
}

// Its third: a code file's external attributes became 0xfffffff4, whose MS-DOS directory bit made
// LibTorch's ZIP reader return it empty, and the importer terminated the process on the empty code.
TEST(FuzzRegressions, CheckpointWithACodeFileMarkedAsADirectory) {
  const std::string bytes = read_input_file(
      testing::fuzz_regression("checkpoint", "directory_attribute_libtorch_terminate.pt"));
  expect_refused(bytes,
                 "entry 'archive/code/__torch__/___torch_mangle_9.py' is marked as a "
                 "directory but is a file");
}

TEST(ZipArchive, TrailingBytesAndEmptyInputAreRefused) {
  expect_refused(weights() + "x", "no end-of-central-directory record");
  expect_refused("", "shorter than an end-of-central-directory record");
  expect_refused(std::string(100, '\0'), "no end-of-central-directory record");
}

TEST(ZipArchive, StoredArchivesReadBackAndPassTheCheck) {
  const std::vector<ZipEntry> entries{{"a.npy", std::string("\x93NUMPY\0\x01", 8)},
                                      {"empty.npy", ""},
                                      {"dir/b.txt", std::string(100000, 'x')}};
  const std::string bytes = stored_zip_archive(entries);
  EXPECT_EQ(check_zip_archive(bytes, "a.npz"), 3u);
  const std::vector<ZipEntry> back = read_zip_archive(bytes, "a.npz");
  ASSERT_EQ(back.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back[i].name, entries[i].name);
    EXPECT_EQ(back[i].contents, entries[i].contents);
  }
  EXPECT_EQ(stored_zip_archive(entries), bytes);  // reproducible: no clock in the archive
  expect_refused(bytes.substr(0, bytes.size() - 1), "end-of-central-directory");
}

TEST(ZipArchive, DeflatedEntriesReadUncompressed) {
  // The bundled weights are a LibTorch archive; every entry reads back at its recorded size.
  std::size_t total = 0;
  for (const ZipEntry& entry : read_zip_archive(weights(), "weights.pt"))
    total += entry.contents.size();
  EXPECT_GT(total, 100000u);
}

}  // namespace
}  // namespace graspecmf
