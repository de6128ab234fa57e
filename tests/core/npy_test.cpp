#include "graspecmf/core/npy.hpp"

#include <gtest/gtest.h>

#include "graspecmf/core/error.hpp"
#include "test_support.hpp"

namespace graspecmf {
namespace {

using testing::expect_error;

// A .npy file with the given header dictionary and data bytes.
std::string npy(const std::string& dictionary, const std::string& data) {
  std::string header = dictionary;
  header.append(63 - (10 + header.size()) % 64, ' ');
  header += '\n';
  std::string out = "\x93NUMPY\x01";
  out.push_back('\0');
  out.push_back(static_cast<char>(header.size()));
  out.push_back('\0');
  return out + header + data;
}

TEST(Npy, WrittenArraysParseBackBitForBitInEveryShape) {
  for (const std::vector<std::size_t>& shape :
       std::vector<std::vector<std::size_t>>{{}, {0}, {5}, {2, 17}, {3, 4, 4}, {0, 3}}) {
    NpyArray array{shape, {}};
    std::size_t count = 1;
    for (const std::size_t n : shape) count *= n;
    for (std::size_t i = 0; i < count; ++i)
      array.values.push_back(0.1 * static_cast<double>(i) - 1e-300);
    const std::string bytes = npy_bytes(array);
    EXPECT_EQ((bytes.find('\n') + 1) % 64, 0u);  // data aligned as NumPy aligns it
    const NpyArray back = parse_npy(bytes, "a.npy");
    EXPECT_EQ(back.shape, shape);
    EXPECT_EQ(back.values, array.values);
  }
  expect_error([] { npy_bytes({{2, 2}, {1, 2, 3}}); }, "does not match its shape");
}

TEST(Npy, Float32AndEveryShapeSpellingRead) {
  const float values[2] = {1.5f, -2.25f};
  const std::string data(reinterpret_cast<const char*>(values), sizeof values);
  const NpyArray array =
      parse_npy(npy("{'descr': '<f4', 'fortran_order': False, 'shape': (2,), }", data), "f");
  EXPECT_EQ(array.values, (std::vector<double>{1.5, -2.25}));
  const NpyArray matrix =
      parse_npy(npy("{'shape': (1, 2), 'fortran_order': False, 'descr': '<f4'}", data), "f");
  EXPECT_EQ(matrix.shape, (std::vector<std::size_t>{1, 2}));
}

TEST(Npy, BadArraysGetOneClearError) {
  const std::string eight(8, '\0');
  expect_error([&] { parse_npy("hello", "x.npy"); }, "x.npy: not a .npy array");
  expect_error(
      [&] {
        parse_npy(npy("{'descr': '>f8', 'fortran_order': False, 'shape': (1,), }", eight), "x");
      },
      "not '>f8'");
  expect_error(
      [&] {
        parse_npy(npy("{'descr': '<f8', 'fortran_order': True, 'shape': (1,), }", eight), "x");
      },
      "C order");
  expect_error(
      [&] { parse_npy(npy("{'descr': '|O', 'fortran_order': False, 'shape': (), }", eight), "x"); },
      "pickled Python objects");
  expect_error(
      [&] {
        parse_npy(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (2,), }", eight), "x");
      },
      "does not match its shape");
  expect_error(
      [&] {
        parse_npy(
            npy("{'descr': '<f8', 'fortran_order': False, 'shape': (4294967296, 4294967296, 2), }",
                eight),
            "x");
      },
      "does not match its shape");
  expect_error(
      [&] {
        parse_npy(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1x,), }", eight), "x");
      },
      "malformed array shape");
  const std::string whole = npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1,), }", eight);
  expect_error([&] { parse_npy(whole.substr(0, 20), "x"); }, "truncated");
  // Found by fuzz_grasps: a version-2 file too short for its 4-byte header length (the fuzz
  // input's first byte selects the GraspNet decoder).
  const std::string found =
      testing::read_file(testing::fuzz_regression("grasps", "npy_version2_short_header"));
  expect_error([&] { parse_npy(std::string_view(found).substr(1), "x"); }, "truncated .npy header");
}

}  // namespace
}  // namespace graspecmf
