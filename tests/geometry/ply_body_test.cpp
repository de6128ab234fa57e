#include "graspecmf/geometry/ply_body.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "graspecmf/core/error.hpp"
#include "test_support.hpp"

namespace graspecmf::geometry {
namespace {

using graspecmf::testing::expect_error;

// Reads the columns wanted from the PLY file held in bytes.
std::vector<PlyColumn> columns_of(const std::string& bytes,
                                  const std::vector<std::pair<std::string, std::string>>& wanted) {
  const PlyHeader header = read_ply_header("t.ply", bytes, bytes.size());
  return read_ply_columns("t.ply", bytes, header, wanted);
}

// The n-byte big-endian representation of bits.
std::string big_endian(std::uint64_t bits, int n) {
  std::string out;
  for (int i = n - 1; i >= 0; --i) out += static_cast<char>((bits >> (8 * i)) & 0xff);
  return out;
}

// Every PLY value type decodes exactly in big-endian order, signed ones with their sign, and a
// list of an unwanted property is skipped.
TEST(PlyBody, BigEndianValuesOfEveryTypeDecodeExactly) {
  std::string bytes =
      "ply\nformat binary_big_endian 1.0\nelement thing 1\nproperty char a\nproperty uchar b\n"
      "property short c\nproperty ushort d\nproperty int e\nproperty uint f\nproperty float g\n"
      "property double h\nproperty list ushort int skipped\nproperty list char int kept\n"
      "end_header\n";
  bytes += big_endian(0xfe, 1) + big_endian(0xfe, 1) + big_endian(0x8000, 2) +
           big_endian(0xffff, 2) + big_endian(0xffffffff, 4) + big_endian(0xffffffff, 4);
  float g = -0.1f;
  double h = 1.0 / 3.0;
  std::uint32_t g_bits = 0;
  std::uint64_t h_bits = 0;
  std::memcpy(&g_bits, &g, 4);
  std::memcpy(&h_bits, &h, 8);
  bytes += big_endian(g_bits, 4) + big_endian(h_bits, 8);
  bytes += big_endian(2, 2) + big_endian(7, 4) + big_endian(8, 4);
  bytes += big_endian(2, 1) + big_endian(0x80000000, 4) + big_endian(5, 4);
  std::vector<std::pair<std::string, std::string>> wanted;
  for (const char* name : {"a", "b", "c", "d", "e", "f", "g", "h", "kept"}) {
    wanted.emplace_back("thing", name);
  }
  const std::vector<PlyColumn> columns = columns_of(bytes, wanted);
  const std::vector<double> expected = {-2, 254, -32768, 65535, -1, 4294967295.0, double(g), h};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(columns[i].values, std::vector<double>{expected[i]}) << wanted[i].second;
    EXPECT_TRUE(columns[i].starts.empty());
  }
  EXPECT_EQ(columns[8].values, (std::vector<double>{-2147483648.0, 5}));
  EXPECT_EQ(columns[8].starts, (std::vector<std::size_t>{0, 2}));
}

// Ascii values are whitespace-separated tokens; line breaks carry no meaning.
TEST(PlyBody, AsciiListsOfEveryLengthIncludingZero) {
  const std::string bytes =
      "ply\nformat ascii 1.0\nelement face 3\nproperty list uchar int vertex_indices\n"
      "property float w\nend_header\n3 0 1 2 0.5\n0 -1e3\n4\t5 6\r\n7 8 +2\n\n";
  const std::vector<PlyColumn> columns =
      columns_of(bytes, {{"face", "vertex_indices"}, {"face", "w"}});
  EXPECT_EQ(columns[0].values, (std::vector<double>{0, 1, 2, 5, 6, 7, 8}));
  EXPECT_EQ(columns[0].starts, (std::vector<std::size_t>{0, 3, 3, 7}));
  EXPECT_EQ(columns[1].values, (std::vector<double>{0.5, -1000, 2}));
}

TEST(PlyBody, DamagedDataIsOneClearError) {
  const std::string ascii =
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
      "property list uchar int i\nend_header\n";
  const std::vector<std::pair<std::string, std::string>> both = {{"vertex", "x"}, {"vertex", "i"}};
  expect_error([&] { columns_of(ascii + "1 1 0\n2 1 x\n", both); }, "'x' is not a number");
  expect_error([&] { columns_of(ascii + "1 1 0.5\n2 0 0\n", both); }, "'0.5' is not an integer");
  expect_error([&] { columns_of(ascii + "1 1 0\n2 3 0 1\n", both); }, "ends early (truncated?)");
  expect_error([&] { columns_of(ascii + "1 1 0\n2 1 0 9\n", both); },
               "goes on after the elements its header declares");
  // The list length 200 cannot fit in the 7 bytes left: refused before reading on.
  expect_error([&] { columns_of(ascii + "1 200 0 1 2 3 4 5\n", both); },
               "a PLY list is longer than the data left");
  const std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1\n"
      "property list char uint i\nend_header\n";
  expect_error([&] { columns_of(binary + std::string(1, '\xff') + std::string(3, '\0'), {}); },
               "a PLY list has a negative length");
  expect_error([&] { columns_of(binary + std::string(1, '\x02') + std::string(4, '\0'), {}); },
               "a PLY list is longer than the data left");
  expect_error([&] { columns_of(binary + std::string(1, '\x00') + "\n", {}); },
               "goes on after the elements");
  expect_error(
      [&] {
        columns_of(binary + std::string(1, '\x00'), {{"vertex", "x"}});
      },
      "no property 'x' of an element 'vertex'");
}

}  // namespace
}  // namespace graspecmf::geometry
