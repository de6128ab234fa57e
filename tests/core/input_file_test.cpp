#include "graspecmf/core/input_file.hpp"

#include <gtest/gtest.h>

#include "graspecmf/core/error.hpp"
#include "test_support.hpp"

namespace graspecmf {
namespace {
namespace fs = std::filesystem;

using testing::ScratchDir;
using testing::write_file;

// The Error message of read_input_file(path), empty if it reads.
std::string read_error(const fs::path& path) {
  try {
    read_input_file(path);
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

TEST(InputFile, LowerExtension) {
  EXPECT_EQ(lower_extension("a/Mug.OBJ"), ".obj");
  EXPECT_EQ(lower_extension("cloud.Ply"), ".ply");
  EXPECT_EQ(lower_extension("noext"), "");
}

TEST(InputFile, ReadsEveryByte) {
  const ScratchDir dir;
  const std::string bytes("a\0b\r\n\xff", 6);
  write_file(dir / "f.bin", bytes);
  EXPECT_EQ(read_input_file(dir / "f.bin"), bytes);
  write_file(dir / "empty.txt", "");
  EXPECT_EQ(read_input_file(dir / "empty.txt"), "");
}

TEST(InputFile, MissingFoldersAndHugeFilesAreOneLineErrors) {
  const ScratchDir dir;
  EXPECT_NE(read_error(dir / "absent.obj").find("no such file"), std::string::npos);
  EXPECT_NE(read_error(dir.path()).find("not a regular file"), std::string::npos);
  // A sparse file one byte over the cap: refused from its size, nothing allocated or read.
  write_file(dir / "huge.obj", "");
  fs::resize_file(dir / "huge.obj", kMaxInputFileBytes + 1);
  const std::string message = read_error(dir / "huge.obj");
  EXPECT_NE(message.find("over 1 GiB"), std::string::npos) << message;
  EXPECT_NE(message.find("huge.obj"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  // A reader with a lower cap (JSON configs) names it.
  write_file(dir / "five.json", "12345");
  EXPECT_EQ(read_input_file(dir / "five.json", 5), "12345");
  graspecmf::testing::expect_error([&] { read_input_file(dir / "five.json", 4); },
                                   "five.json: the file has 5 bytes; files over 4 bytes");
}

}  // namespace
}  // namespace graspecmf
