#include "graspecmf/core/atomic_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>

#include "graspecmf/core/error.hpp"
#include "test_support.hpp"

namespace graspecmf {
namespace {
namespace fs = std::filesystem;

using testing::read_file;
using testing::ScratchDir;

TEST(AtomicFile, WritesText) {
  ScratchDir dir;
  write_file_atomically(dir / "a.txt", "hello\n");
  EXPECT_EQ(read_file(dir / "a.txt"), "hello\n");
  EXPECT_EQ(dir.num_files(), 1u);
}

TEST(AtomicFile, FailedWriterKeepsOldFileAndLeavesNoTemporary) {
  ScratchDir dir;
  write_file_atomically(dir / "a.txt", "old");
  EXPECT_THROW(write_atomically(dir / "a.txt",
                                [](const fs::path& tmp) {
                                  std::ofstream(tmp) << "partial";
                                  throw std::runtime_error("writer failed");
                                }),
               std::runtime_error);
  EXPECT_EQ(read_file(dir / "a.txt"), "old");
  EXPECT_EQ(dir.num_files(), 1u);
}

TEST(AtomicFile, MissingFolderIsAClearError) {
  ScratchDir dir;
  try {
    write_file_atomically(dir / "no" / "such" / "a.txt", "x");
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace graspecmf
