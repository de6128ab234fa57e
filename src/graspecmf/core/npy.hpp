#pragma once
// NumPy .npy arrays of numbers held in memory: a validating parser (little-endian float32/64,
// integers of 1 to 8 bytes or bools, C order, any shape; read as float64) and a float64 writer.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace graspecmf {

// A dense array: its shape and its values in C (row-major) order.
struct NpyArray {
  std::vector<std::size_t> shape;
  std::vector<double> values;
  bool integral = false;  // the file held integers or bools (parse_npy)
};

// Parses .npy bytes (format versions 1 to 3). Throws Error "<what>: <why>" unless they hold a
// little-endian numeric or bool array in C order whose data matches its shape; an array of
// Python objects (NumPy's pickled 'O' type) is refused with a message that says so.
NpyArray parse_npy(std::string_view bytes, const std::string& what);

// The .npy (version 1.0) bytes of the array as little-endian float64. Throws Error if the number of
// values does not match the shape.
std::string npy_bytes(const NpyArray& array);

}  // namespace graspecmf
